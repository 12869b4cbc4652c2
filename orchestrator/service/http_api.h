#pragma once

#include "orchestrator/service/auth.h"
#include "orchestrator/service/scheduler.h"
#include "orchestrator/service/service_metrics.h"
#include "orchestrator/service/service_options.h"
#include "orchestrator/service/sweep_planner.h"

namespace httplib {
class Server;
}

namespace slamsweep::orchestrator::service {

// httplib.h is included by .cc files only, after everything else: it brings <resolv.h>, whose `_res`
// macro breaks Eigen's headers when they come later.

/// What the HTTP handlers work with.
struct ApiContext {
  Scheduler& scheduler;
  ServiceMetrics& metrics;
  SweepPlanner planner;
  const ServiceOptions& options;
  BearerAuth auth;
};

/// Every route of the service on `server` (cpp-httplib):
///   POST /api/sweeps (YAML body; ?priority=N&name=FILE&base=DIR), GET /api/sweeps, GET /api/sweeps/ID,
///   GET /api/sweeps/ID/runs, POST /api/sweeps/ID/cancel, GET /api/sweeps/ID/{junit.xml,summary.json,
///   summary.csv}, GET /api/sweeps/ID/report (the report's file list), GET / and /sweeps/ID (pages),
///   GET /sweeps/ID/report/... (the report's files), /static/service.css, /healthz, /metrics.
/// Writes (POST) need the bearer token when one is configured (401 without it, logged without the
/// token); reads are open. The report's files are served with the report's Content-Security-Policy,
/// everything else with the page policy.
void RegisterRoutes(httplib::Server& server, ApiContext& context);

/// The CSP of the report's files: Jenkins' default, which the report is built for.
inline constexpr const char* kReportContentSecurityPolicy =
    "sandbox allow-same-origin; default-src 'none'; img-src 'self'; style-src 'self';";

/// The CSP of the service's own pages and API answers: the report's rules (no script, no inline style,
/// no data: URI, only this server's images and stylesheets) without `sandbox`, since a sandboxed page
/// may not follow its <meta http-equiv="refresh"> and the page's live state is that refresh.
inline constexpr const char* kPageContentSecurityPolicy =
    "default-src 'none'; img-src 'self'; style-src 'self'; base-uri 'none'; form-action 'none'; "
    "frame-ancestors 'none';";

}  // namespace slamsweep::orchestrator::service
