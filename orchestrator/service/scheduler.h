#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <vector>

#include "orchestrator/run/run_spec.h"
#include "orchestrator/service/queue_store.h"
#include "orchestrator/service/service_metrics.h"
#include "orchestrator/service/sweep_entry.h"
#include "orchestrator/service/sweep_table.h"
#include "orchestrator/service/sweep_views.h"
#include "orchestrator/supervisor/executor.h"

namespace slamsweep::orchestrator::service {

struct SchedulerOptions {
  /// Worker slots shared by every sweep (local executor); runs handed to Slurm at once (slurm).
  std::size_t jobs = 1;
  /// SIGTERM/SIGINT: how long running runs may finish before they are stopped and queued again.
  double drain_grace_s = 600.0;
  /// A run whose worker was interrupted without a result (not by a cancel or a drain) is queued again
  /// up to this many attempts, then recorded as failed.
  int max_attempts = 3;
};

/// The service's one worker pool, shared by every sweep: the queue held in DATA/queue.sqlite
/// (SweepTable), runs started through one Executor (the same local or Slurm executor as `slamsweep
/// run`), each sweep's results written into its own result directory (sweep_lifecycle.h). Which run
/// starts next is the fair share's choice (fair_share.h); a run whose identical twin has an ok result
/// in another sweep is linked from there, not run (run_reuse.h), and while its twin is running it waits.
///
/// The loop itself is the Supervisor's (supervisor/supervisor.h), fed by a ServiceRunSource.
///
/// Threads: Run() is the scheduler's own loop and must be called from the thread that owns the
/// executor (its children's parent-death signal follows that thread); every other member may be called
/// from any thread (the HTTP handlers).
class Scheduler {
 public:
  Scheduler(QueueStore& queue, std::mutex& queue_mutex, const std::filesystem::path& data_dir, SchedulerOptions options,
            ServiceMetrics& metrics);
  ~Scheduler();

  /// Loads the queue after a (re)start: runs left running are queued again, and unfinished sweeps are
  /// resumed. Call before Run().
  void Recover();

  /// The loop: starts, records and finishes runs until Drain()/an interruption (SIGTERM, SIGINT,
  /// SIGHUP under an InterruptionGuard) and then until the running runs ended or the grace period ran
  /// out (those left are stopped and queued again). Returns when drained.
  void Run(Executor& executor);

  /// Adds a planned, validated sweep: it is queued durably before this returns.
  QueuedSweep Submit(QueuedSweep sweep, const std::vector<RunSpec>& runs);
  /// Cancels a sweep: queued runs are dropped, running ones stopped, finished results kept.
  CancelOutcome Cancel(std::int64_t sweep_id);
  /// Stops accepting work and drains (as SIGTERM does).
  void Drain();
  bool Draining() const { return draining_.load(); }

  std::vector<SweepView> Sweeps() const { return sweeps_.Sweeps(); }
  std::optional<SweepView> Sweep(std::int64_t id) const { return sweeps_.Sweep(id); }
  std::optional<std::vector<RunView>> Runs(std::int64_t sweep_id) const { return sweeps_.Runs(sweep_id); }
  /// Sweeps not finished (queued or running): what the queued-sweeps limit counts.
  std::size_t UnfinishedSweeps() const { return sweeps_.UnfinishedSweeps(); }

  /// Sweeps whose report is to be written, oldest first; the report thread takes them one at a time.
  std::optional<QueuedSweep> TakeReportJob() { return sweeps_.TakeReportJob(); }
  void ReportWritten(std::int64_t sweep_id, bool ok) { sweeps_.ReportWritten(sweep_id, ok); }

 private:
  std::filesystem::path data_dir_;
  SchedulerOptions options_;
  ServiceMetrics& metrics_;
  SweepTable sweeps_;
  std::atomic<bool> draining_ = false;
};

}  // namespace slamsweep::orchestrator::service
