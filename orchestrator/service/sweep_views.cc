#include "orchestrator/service/sweep_views.h"

#include "orchestrator/service/sweep_entry.h"
#include "orchestrator/sweep/status.h"

namespace slamsweep::orchestrator::service {

RunCounts CountRuns(const std::vector<RunView>& runs) {
  RunCounts counts;
  counts.total = runs.size();
  for (const RunView& run : runs) {
    switch (run.state) {
      case QueuedRunState::kQueued:
        ++counts.queued;
        break;
      case QueuedRunState::kRunning:
        ++counts.running;
        break;
      case QueuedRunState::kOk:
        ++counts.ok;
        break;
      case QueuedRunState::kFailed:
        ++counts.failed;
        break;
      case QueuedRunState::kReused:
        ++counts.reused;
        break;
      case QueuedRunState::kCancelled:
        ++counts.cancelled;
        break;
    }
  }
  return counts;
}

std::vector<RunView> RunViewsOf(const SweepEntry& entry) {
  std::vector<RunView> runs;
  runs.reserve(entry.runs.size());
  for (const RunEntry& run : entry.runs) runs.push_back(run.view);
  return runs;
}

SweepView SweepViewOf(const SweepEntry& entry, std::size_t slots, std::chrono::steady_clock::time_point now) {
  SweepView view;
  view.sweep = entry.sweep;
  view.sweep.config_text.clear();
  view.counts = CountRuns(RunViewsOf(entry));
  view.report = entry.report;
  if (entry.active) {
    view.eta = EstimateRemaining(entry.finished_here, entry.finished_here + view.counts.queued + view.counts.running,
                                 slots, now - entry.activated_at);
  }
  return view;
}

}  // namespace slamsweep::orchestrator::service
