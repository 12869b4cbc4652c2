#include "orchestrator/service/scheduler.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "orchestrator/process/interruption.h"
#include "orchestrator/process/wake_up.h"
#include "orchestrator/service/run_reuse.h"
#include "orchestrator/service/sweep_lifecycle.h"
#include "orchestrator/run/run_folder.h"
#include "orchestrator/sweep/sweep_steps.h"

namespace slamsweep::orchestrator::service {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

Scheduler::Scheduler(QueueStore& queue, std::mutex& queue_mutex, const std::filesystem::path& data_dir,
                     SchedulerOptions options, ServiceMetrics& metrics)
    : data_dir_(data_dir),
      options_(options),
      metrics_(metrics),
      sweeps_(queue, queue_mutex, data_dir / "sweeps", options.jobs) {}

Scheduler::~Scheduler() = default;

void Scheduler::Recover() { sweeps_.Load(); }

QueuedSweep Scheduler::Submit(QueuedSweep sweep, const std::vector<RunSpec>& runs) {
  sweep = sweeps_.Add(std::move(sweep), runs);
  spdlog::info("sweep {} '{}' submitted by {}: {} runs, priority {}", sweep.id, sweep.name, sweep.submitter,
               runs.size(), sweep.priority);
  RequestWakeUp();
  return sweep;
}

CancelOutcome Scheduler::Cancel(std::int64_t sweep_id) {
  const CancelOutcome outcome = sweeps_.RequestCancel(sweep_id);
  if (!outcome.known || outcome.finished_as) return outcome;
  spdlog::info("sweep {}: cancel requested", sweep_id);
  RequestWakeUp();
  return outcome;
}

void Scheduler::Drain() {
  draining_ = true;
  RequestWakeUp();
}

void Scheduler::ActivateWaitingSweeps() {
  const std::vector<SweepEntry*> waiting =
      sweeps_.Select([](const SweepEntry& entry) { return !entry.active && !IsFinished(entry.sweep.state); });
  for (SweepEntry* entry : waiting) ActivateSweep(sweeps_, *entry, data_dir_);
}

void Scheduler::HandleCancels(Executor& executor) {
  const std::vector<SweepEntry*> cancelled =
      sweeps_.Select([](const SweepEntry& entry) { return entry.active && entry.sweep.cancel_requested; });
  for (SweepEntry* entry : cancelled) {
    for (const std::size_t index : entry->pending) {
      sweeps_.SetRunState(*entry, index, QueuedRunState::kCancelled, false, std::nullopt, "sweep cancelled");
    }
    entry->pending.clear();
    for (RunEntry& run : entry->runs) {
      if (run.view.state != QueuedRunState::kRunning || run.stop_sent) continue;
      executor.Stop(run.view.run_id);
      run.stop_sent = true;
    }
  }
}

void Scheduler::StartRun(Executor& executor, SweepEntry& entry, std::size_t index) {
  RunEntry& run = entry.runs[index];
  const std::filesystem::path run_dir = PrepareRunFolder(entry.sweep.result_dir, run.spec);
  sweeps_.SetRunState(entry, index, QueuedRunState::kRunning, true, std::nullopt, "");
  executor.Start(run.spec, run_dir);
  running_[run.view.run_id] = entry.sweep.id;
  ++entry.running;
  entry.last_start_tick = ++tick_;
}

void Scheduler::RecordStartFailure(SweepEntry& entry, std::size_t index, const std::exception& error) {
  const RunEntry& run = entry.runs[index];
  const nlohmann::json result = MissingResult(run.spec, error.what(), false);
  try {
    entry.store->RecordRun(entry.store_sweep_id, ToJson(run.spec), result,
                           std::filesystem::path("runs") / run.view.run_id);
  } catch (const std::exception& store_error) {
    spdlog::error("sweep {}: cannot record {}: {}", entry.sweep.id, run.view.run_id, store_error.what());
  }
  sweeps_.SetRunState(entry, index, QueuedRunState::kFailed, false, std::nullopt,
                      std::string("internal: ") + error.what());
}

void Scheduler::StartRuns(Executor& executor) {
  if (draining_ || InterruptionGuard::Interrupted()) return;
  while (executor.Running() < options_.jobs) {
    const auto started = Clock::now();
    SweepEntry* entry = NextSweep(sweeps_.Select(WantsASlot), running_);
    if (entry == nullptr) {
      slot_freed_.clear();  // nothing waited for those slots: no scheduling latency to count
      return;
    }
    const std::size_t index = TakeStartableRun(*entry, running_);
    if (ReuseIdenticalRun(sweeps_, *entry, index, metrics_)) {
      sweeps_.CountFinished(*entry);
      continue;
    }
    try {
      StartRun(executor, *entry, index);
    } catch (const std::exception& error) {
      // The run's folder could not be prepared (disk full, permissions): a failed run, as a worker
      // that cannot start is one; the sweep goes on.
      RecordStartFailure(*entry, index, error);
      continue;
    }
    // From the moment a slot was free (the earliest unclaimed freeing) to this start.
    Clock::time_point since = started;
    if (!slot_freed_.empty()) {
      since = slot_freed_.front().second;
      slot_freed_.erase(slot_freed_.begin());
    }
    metrics_.SchedulingOverhead(SecondsSince(since));
  }
}

void Scheduler::RecordEnding(const WorkerEnding& ending) {
  const auto started = Clock::now();
  const auto found = running_.find(ending.run_id);
  if (found == running_.end()) return;
  const std::int64_t sweep_id = found->second;
  running_.erase(found);
  SweepEntry& entry = sweeps_.Entry(sweep_id);
  const std::size_t index = entry.by_run_id.at(ending.run_id);
  RunEntry& run = entry.runs[index];
  --entry.running;
  run.stop_sent = false;
  std::optional<FinishedRun> finished;
  try {
    finished = RecordWorkerEnding(run.spec, ending, entry.sweep.result_dir, *entry.store, entry.store_sweep_id);
  } catch (const std::exception& error) {
    spdlog::error("sweep {}: cannot record {}: {}", sweep_id, ending.run_id, error.what());
    finished = FinishedRun{ending.run_id, false, std::string("internal: ") + error.what(), 0.0};
  }
  if (finished) {
    const QueuedRunState state = finished->ok ? QueuedRunState::kOk : QueuedRunState::kFailed;
    sweeps_.SetRunState(entry, index, state, false,
                        finished->wall_s > 0 ? std::optional<double>(finished->wall_s) : std::nullopt,
                        finished->reason);
    metrics_.RunFinished(state, finished->wall_s, true);
    sweeps_.CountFinished(entry);
  } else if (entry.sweep.cancel_requested) {
    sweeps_.SetRunState(entry, index, QueuedRunState::kCancelled, false, std::nullopt,
                        "sweep cancelled: " + ending.reason);
  } else if (draining_ || InterruptionGuard::Interrupted() || run.view.attempt < options_.max_attempts) {
    // Stopped by a drain (or killed from outside): it runs again, from scratch, when the server resumes.
    sweeps_.SetRunState(entry, index, QueuedRunState::kQueued, false, std::nullopt, "");
    entry.pending.push_front(index);
  } else {
    const nlohmann::json result =
        MissingResult(run.spec, fmt::format("{} ({} attempts interrupted)", ending.reason, run.view.attempt), true);
    WriteJsonAtomically(RunFolder(entry.sweep.result_dir, run.spec.run_id) / "result.json", result);
    entry.store->RecordRun(entry.store_sweep_id, ToJson(run.spec), result,
                           std::filesystem::path("runs") / run.spec.run_id);
    sweeps_.SetRunState(entry, index, QueuedRunState::kFailed, false, std::nullopt, result.value("reason", ""));
    metrics_.RunFinished(QueuedRunState::kFailed, 0.0, false);
  }
  // The scheduling latency of the run that takes this slot counts from here, recording included.
  slot_freed_.emplace_back(ending.run_id, started);
}

void Scheduler::FinishSweeps() {
  const std::vector<SweepEntry*> done = sweeps_.Select(
      [](const SweepEntry& entry) { return entry.active && entry.pending.empty() && entry.running == 0; });
  for (SweepEntry* entry : done) {
    const bool cancelled = entry->sweep.cancel_requested;
    FinishSweep(sweeps_, *entry, cancelled ? QueuedSweepState::kCancelled : QueuedSweepState::kOk,
                cancelled ? "cancelled; finished results kept" : "");
  }
}

void Scheduler::WaitForWork(Executor& executor) {
  if (executor.Running() > 0) {
    std::vector<WorkerEnding> endings = executor.Wait();
    if (endings.empty()) {
      // A wake-up, or an interruption (then Wait returns at once while workers drain): sleep a little
      // (up to a wake-up), so the loop does not spin; drained workers are reaped at the next turn.
      if (InterruptionGuard::Interrupted()) SleepUnlessWoken(0.2);
      TakeWakeUpRequest();
    }
    for (const WorkerEnding& ending : endings) RecordEnding(ending);
    return;
  }
  // Nothing running: sleep until a submission or cancel wakes us (or a signal arrives: signals are
  // taken only inside such waits).
  SleepUnlessWoken(1.0);
  TakeWakeUpRequest();
}

void Scheduler::Run(Executor& executor) {
  for (;;) {
    const bool interrupted = InterruptionGuard::Interrupted();
    if (interrupted && !draining_) {
      spdlog::info("{} received: draining (no new runs; running ones may finish for {:g} s)",
                   InterruptionGuard::Signal() == SIGTERM ? "SIGTERM" : "signal", options_.drain_grace_s);
      draining_ = true;
    }
    if (draining_ && !drain_deadline_) {
      drain_deadline_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(options_.drain_grace_s));
    }
    if (!draining_) ActivateWaitingSweeps();
    HandleCancels(executor);
    StartRuns(executor);
    FinishSweeps();
    if (draining_) {
      if (executor.Running() == 0) break;
      if (Clock::now() >= *drain_deadline_) {
        spdlog::warn("drain grace period over: stopping {} running runs; they are queued again", executor.Running());
        for (const WorkerEnding& ending : executor.TerminateAll()) RecordEnding(ending);
        FinishSweeps();
        break;
      }
    }
    WaitForWork(executor);
  }
  sweeps_.CloseAll();
}

}  // namespace slamsweep::orchestrator::service
