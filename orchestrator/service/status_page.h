#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "orchestrator/service/service_metrics.h"
#include "orchestrator/service/sweep_views.h"

namespace slamsweep::orchestrator::service {

// The service's pages, rendered on the server: no script, no inline style, no data: URI (the report's
// rules), one stylesheet at /static/service.css, and a <meta http-equiv="refresh"> every few seconds
// for the live state. Every text that came from a submission is escaped.

/// GET /: every sweep, newest first, with its state, progress, ETA and links (report, JUnit, summaries).
std::string RenderIndexPage(const std::vector<SweepView>& sweeps, const QueueGauges& gauges);

/// GET /sweeps/ID: one sweep and its runs.
std::string RenderSweepPage(const SweepView& sweep, const std::vector<RunView>& runs);

/// GET /static/service.css.
std::string_view ServiceStyleSheet();

/// & < > " ' escaped for HTML text and attribute values.
std::string HtmlEscape(std::string_view text);

/// Seconds between refreshes of the pages.
inline constexpr int kPageRefreshSeconds = 5;

}  // namespace slamsweep::orchestrator::service
