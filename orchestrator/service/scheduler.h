#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "orchestrator/run/run_spec.h"
#include "orchestrator/service/queue_store.h"
#include "orchestrator/service/service_metrics.h"
#include "orchestrator/store/results_store.h"
#include "orchestrator/sweep/executor.h"
#include "orchestrator/sweep/output_lock.h"

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

/// A run as the API shows it.
struct RunView {
  std::string run_id;
  std::string state;
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
  /// "none" until the sweep finished, then "writing", "ready" or "failed".
  std::string report = "none";
};

/// The service's one worker pool, shared by every sweep: the queue held in DATA/queue.sqlite, runs
/// started through one Executor (the same local or Slurm executor as `slamsweep run`), each sweep's
/// results written into its own result directory with the same steps as `slamsweep run`
/// (orchestrator/sweep/sweep_steps.h), so report, merge and history read them as they read a run's.
///
/// Order: among sweeps with a run ready to start, the highest priority first; between equal
/// priorities, the sweep with the fewest runs running, then the one that waited longest since it last
/// started a run (fair shares of the pool). A run whose identical twin (same run id, build identity
/// and evaluation) has an ok result in another sweep is linked from there, not run; while its twin
/// is running it waits for it.
///
/// Threads: Run() is the scheduler's own loop and must be called from the thread that owns the
/// executor (its children's parent-death signal follows that thread); every other member may be called
/// from any thread (the HTTP handlers).
class Scheduler {
 public:
  Scheduler(QueueStore& queue, std::mutex& queue_mutex, const std::filesystem::path& data_dir, SchedulerOptions options,
            ServiceMetrics& metrics);
  ~Scheduler();

  /// Loads the queue after a (re)start: runs left "running" are queued again, and unfinished sweeps are
  /// resumed. Call before Run().
  void Recover();

  /// The loop: starts, records and finishes runs until Drain()/an interruption (SIGTERM, SIGINT,
  /// SIGHUP under an InterruptionGuard) and then until the running runs ended or the grace period ran
  /// out (those left are stopped and queued again). Returns when drained.
  void Run(Executor& executor);

  /// Adds a planned, validated sweep: it is queued durably before this returns.
  QueuedSweep Submit(QueuedSweep sweep, const std::vector<RunSpec>& runs);
  /// Cancels a sweep: queued runs are dropped, running ones stopped, finished results kept. False when
  /// the sweep is unknown; the state in `state_after` ("cancelled", or a finished sweep's own state).
  bool Cancel(std::int64_t sweep_id, std::string& state_after);
  /// Stops accepting work and drains (as SIGTERM does).
  void Drain();
  bool Draining() const { return draining_.load(); }

  std::vector<SweepView> Sweeps() const;
  std::optional<SweepView> Sweep(std::int64_t id) const;
  std::optional<std::vector<RunView>> Runs(std::int64_t sweep_id) const;
  /// Sweeps not finished (queued or running): what the queued-sweeps limit counts.
  std::size_t UnfinishedSweeps() const;

  /// Sweeps whose report is to be written, oldest first; the report thread takes them one at a time.
  std::optional<QueuedSweep> TakeReportJob();
  void ReportWritten(std::int64_t sweep_id, bool ok);

 private:
  struct RunEntry {
    RunSpec spec;
    RunView view;
    bool stop_sent = false;
  };
  struct SweepEntry {
    QueuedSweep sweep;
    std::vector<RunEntry> runs;
    std::map<std::string, std::size_t> by_run_id;
    std::string report = "none";
    // Scheduler thread only: the open result directory while the sweep is active.
    bool active = false;
    std::unique_ptr<OutputLock> lock;
    std::optional<ResultsStore> store;
    std::int64_t store_sweep_id = 0;
    std::deque<std::size_t> pending;
    std::size_t running = 0;
    std::uint64_t last_start_tick = 0;
    std::chrono::steady_clock::time_point activated_at;
    std::size_t finished_here = 0;
  };

  // All of these run on the scheduler thread, taking mutex_ only to change what readers see.
  void ActivateWaitingSweeps();
  bool Activate(SweepEntry& entry);
  void HandleCancels(Executor& executor);
  void StartRuns(Executor& executor);
  bool TryReuse(SweepEntry& entry, std::size_t index);
  void StartRun(Executor& executor, SweepEntry& entry, std::size_t index);
  void RecordEnding(const WorkerEnding& ending);
  void FinishSweeps();
  void Finish(SweepEntry& entry, const std::string& state, const std::string& message = {});
  void Fail(SweepEntry& entry, const std::string& message);
  void SetRunState(SweepEntry& entry, std::size_t index, const std::string& state, bool attempt_started,
                   std::optional<double> wall_s, const std::string& reason,
                   std::optional<std::int64_t> reused_from = std::nullopt);
  SweepView ViewOf(const SweepEntry& entry) const;
  SweepEntry* PickSweep();
  void WaitForWork(Executor& executor);
  void Notify();

  QueueStore& queue_;
  std::mutex& queue_mutex_;
  std::filesystem::path data_dir_;
  SchedulerOptions options_;
  ServiceMetrics& metrics_;

  mutable std::mutex mutex_;  // guards sweeps_ and the views inside
  std::map<std::int64_t, std::unique_ptr<SweepEntry>> sweeps_;
  std::deque<std::int64_t> report_jobs_;
  std::atomic<bool> draining_ = false;

  // Scheduler thread only.
  std::map<std::string, std::int64_t> running_;  // run id -> sweep id
  std::uint64_t tick_ = 0;
  std::optional<std::chrono::steady_clock::time_point> drain_deadline_;
  std::vector<std::pair<std::string, std::chrono::steady_clock::time_point>> slot_freed_;
};

}  // namespace slamsweep::orchestrator::service
