#pragma once

#include "orchestrator/service/service_options.h"
#include "orchestrator/service/sweep_planner.h"

namespace slamsweep::orchestrator::service {

/// `slamsweep serve`: refuses an unsafe setup (a non-loopback address without a token, a token file
/// others can read), takes DATA (one server per data folder, an flock like an output directory's),
/// ends the processes a killed predecessor left and queues its runs in flight again, then listens and
/// schedules until SIGTERM/SIGINT/SIGHUP: then it drains (no new runs; running ones get the grace
/// period, the rest are stopped and queued again for the next start) and returns 0.
/// Throws InputError for a setup it refuses (exit code 2).
int RunService(const ServiceOptions& options, const SweepPlanner& planner, const ReportWriter& report_writer);

}  // namespace slamsweep::orchestrator::service
