#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/run/run_status.h"
#include "orchestrator/service/queue_store.h"

namespace slamsweep::orchestrator::service {

struct SweepEntry;

/// A run as the API shows it.
struct RunView {
  std::string run_id;
  QueuedRunState state = QueuedRunState::kQueued;
  int attempt = 0;
  std::optional<std::int64_t> reused_from;
  std::optional<double> wall_s;
  std::string reason;
};

/// Counts of a sweep's runs by state.
struct RunCounts {
  std::size_t total = 0, queued = 0, running = 0, ok = 0, failed = 0, reused = 0, cancelled = 0;
  std::size_t finished() const { return ok + failed + reused; }
};

/// A sweep as the API and the page show it.
struct SweepView {
  QueuedSweep sweep;
  RunCounts counts;
  /// Remaining time at the sweep's throughput so far ("1m20s"); empty before its first run ended.
  std::string eta;
  ReportState report = ReportState::kNone;
};

RunCounts CountRuns(const std::vector<RunView>& runs);

/// The views of `entry`'s runs, in start order.
std::vector<RunView> RunViewsOf(const SweepEntry& entry);

/// `entry` as the API shows it, without its YAML text (large, and of no use to the API). An active
/// sweep's ETA is its throughput since activation over `slots` worker slots, measured up to `now`.
SweepView SweepViewOf(const SweepEntry& entry, std::size_t slots, std::chrono::steady_clock::time_point now);

}  // namespace slamsweep::orchestrator::service
