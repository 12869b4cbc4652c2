#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/run/run_spec.h"
#include "orchestrator/service/queue_store.h"
#include "orchestrator/service/sweep_views.h"
#include "orchestrator/store/results_store.h"
#include "orchestrator/sweep/output_lock.h"

namespace slamsweep::orchestrator::service {

/// One run of a sweep as the scheduler holds it: what it runs and how the API shows it.
struct RunEntry {
  RunSpec spec;
  RunView view;
  /// Scheduler thread only: its worker was asked to stop (the sweep is being cancelled).
  bool stop_sent = false;
};

/// One sweep as the scheduler holds it. The first group is what readers see: only the scheduler
/// thread changes it, and only under the SweepTable's lock. The second group is the scheduler thread's
/// alone: the result directory it holds open while the sweep is active, and the runs' way through the pool.
struct SweepEntry {
  QueuedSweep sweep;
  std::vector<RunEntry> runs;
  std::map<std::string, std::size_t> by_run_id;
  ReportState report = ReportState::kNone;
  bool active = false;
  std::chrono::steady_clock::time_point activated_at;
  /// Runs that ended with a result since activation: the ETA's throughput.
  std::size_t finished_here = 0;

  std::unique_ptr<OutputLock> lock;
  std::optional<ResultsStore> store;
  std::int64_t store_sweep_id = 0;
  /// Indices into `runs` still to start, in start order.
  std::deque<std::size_t> pending;
  std::size_t running = 0;
  /// When it last started a run, on the scheduler's own clock of starts (fair shares).
  std::uint64_t last_start_tick = 0;
};

}  // namespace slamsweep::orchestrator::service
