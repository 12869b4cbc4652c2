#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/supervisor/executor.h"

namespace slamsweep::orchestrator::inline sweep {

/// Runs a sweep's runs on this machine through long-lived workers, one per slot (`WORKER_PROGRAM worker
/// --serve`, orchestrator/worker/worker_service.h), each taking runs one after another: a run costs no
/// process start (the loading of slamsweep's libraries was most of a quick run's overhead), while each SLAM
/// program still runs in its own sandboxed process started by the worker. A worker is started when a run
/// needs a slot and none is idle, in its own process group, with WorkerEnvironment().
/// - A worker that dies (crash, out of memory, killed) loses only the run in hand: that run ends with the
///   reason ("worker: killed by SIGSEGV (signal 11)"), without result.json, and the next run gets a new
///   worker. kill -9 of the supervisor leaves what a per-run worker leaves (each worker stops with its
///   parent and commits no result after the signal), so a resumed sweep neither loses nor repeats a run.
/// - A run taking longer than its program's timeout plus kDefaultWorkerOverheadS gets its worker
///   stopped (SIGTERM to its group, 10 s grace, SIGKILL): that run ends "worker: timed out after ...".
/// Not thread-safe (one supervising thread); Wait() returns early for signals and RequestWakeUp().
class WorkerPool final : public Executor {
 public:
  /// LocalExecutor::kWorkerOverheadS: reading the sequence, writing the input, scoring, writing outputs.
  static constexpr double kDefaultWorkerOverheadS = 600.0;

  /// `worker_overhead_s`: what a run may take beyond its program's timeout (tests shorten it).
  explicit WorkerPool(std::filesystem::path worker_program, double worker_overhead_s = kDefaultWorkerOverheadS);
  /// Closes every worker's socket (idle workers exit), SIGKILLs busy ones and reaps them all.
  ~WorkerPool() override;
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  void Start(const RunSpec& run, const std::filesystem::path& run_dir) override;
  std::vector<WorkerEnding> Wait() override;
  void Stop(const std::string& run_id) override;
  std::vector<WorkerEnding> TerminateAll() override;
  std::size_t Running() const override;
  bool Interrupted() const override;

  /// Worker processes started so far (a test's view of reuse).
  std::size_t WorkersStarted() const { return started_; }

 private:
  using Clock = std::chrono::steady_clock;
  struct Job {
    std::string run_id;
    Clock::time_point started;
    Clock::time_point deadline;
    double timeout_s = 0.0;
  };
  struct Worker {
    pid_t pid = -1;
    int channel = -1;  ///< our end of the socket
    std::string received;
    std::optional<Job> job;
    /// Asked to stop (SIGTERM): why, and when SIGKILL follows.
    enum class Stopping { kNo, kInterrupted, kTimedOut } stopping = Stopping::kNo;
    Clock::time_point kill_at;
    bool killed = false;
    bool exiting = false;  ///< answered an interrupted run: takes no other
  };

  Worker& IdleWorker();
  void Spawn(Worker& worker);
  /// Reads what arrived from `worker`; its run's ending when it answered or died.
  void ReadFrom(Worker& worker);
  /// Reaps a worker whose socket closed, ending its run (if any) with how it died.
  void Bury(Worker& worker);
  void AskToStop(Worker& worker, Worker::Stopping why, Clock::time_point now);
  void EnforceDeadlines(Clock::time_point now);
  /// Waits for data, a signal, a wake-up or the next deadline (capped).
  void Poll();
  void Finish(Worker& worker, WorkerEnding ending);

  std::filesystem::path worker_program_;
  double worker_overhead_s_;
  std::vector<Worker> workers_;
  std::vector<WorkerEnding> ended_;
  std::size_t started_ = 0;
};

}  // namespace slamsweep::orchestrator::inline sweep
