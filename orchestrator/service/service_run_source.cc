#include "orchestrator/service/service_run_source.h"

#include <csignal>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "orchestrator/process/interruption.h"
#include "orchestrator/run/run_folder.h"
#include "orchestrator/service/run_reuse.h"
#include "orchestrator/service/sweep_lifecycle.h"
#include "orchestrator/sweep/sweep_steps.h"

namespace slamsweep::orchestrator::service {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

ServiceRunSource::ServiceRunSource(SweepTable& sweeps, const std::filesystem::path& data_dir,
                                   std::atomic<bool>& draining, int max_attempts, double drain_grace_s,
                                   ServiceMetrics& metrics)
    : sweeps_(sweeps),
      data_dir_(data_dir),
      draining_(draining),
      max_attempts_(max_attempts),
      drain_grace_s_(drain_grace_s),
      metrics_(metrics) {}

void ServiceRunSource::BeginTurn(Executor& executor) {
  if (!draining_) ActivateWaitingSweeps();
  HandleCancels(executor);
}

void ServiceRunSource::ActivateWaitingSweeps() {
  const std::vector<SweepEntry*> waiting =
      sweeps_.Select([](const SweepEntry& entry) { return !entry.active && !IsFinished(entry.sweep.state); });
  for (SweepEntry* entry : waiting) ActivateSweep(sweeps_, *entry, data_dir_);
}

void ServiceRunSource::HandleCancels(Executor& executor) {
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

std::optional<RunStart> ServiceRunSource::Next() {
  if (draining_ || InterruptionGuard::Interrupted()) return std::nullopt;
  for (;;) {
    next_chosen_from_ = Clock::now();
    SweepEntry* entry = NextSweep(sweeps_.Select(WantsASlot), running_);
    if (entry == nullptr) {
      slot_freed_.clear();  // nothing waited for those slots: no scheduling latency to count
      return std::nullopt;
    }
    const std::size_t index = TakeStartableRun(*entry, running_);
    if (ReuseIdenticalRun(sweeps_, *entry, index, metrics_)) {
      sweeps_.CountFinished(*entry);
      continue;
    }
    RunEntry& run = entry->runs[index];
    try {
      const std::filesystem::path run_dir = PrepareRunFolder(entry->sweep.result_dir, run.spec);
      sweeps_.SetRunState(*entry, index, QueuedRunState::kRunning, true, std::nullopt, "");
      next_entry_ = entry;
      next_index_ = index;
      return RunStart{&run.spec, run_dir};
    } catch (const std::exception& error) {
      // The run's folder could not be prepared (disk full, permissions): a failed run, as a worker
      // that cannot start is one; the sweep goes on.
      RecordStartFailure(*entry, index, error);
    }
  }
}

bool ServiceRunSource::StartFailed(const std::exception& error) {
  RecordStartFailure(*next_entry_, next_index_, error);
  return true;
}

void ServiceRunSource::RecordStartFailure(SweepEntry& entry, std::size_t index, const std::exception& error) {
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

void ServiceRunSource::Started(const RunStart& start) {
  SweepEntry& entry = *next_entry_;
  running_[start.run->run_id] = entry.sweep.id;
  ++entry.running;
  entry.last_start_tick = ++tick_;
  // From the moment a slot was free (the earliest unclaimed freeing) to this start.
  Clock::time_point since = next_chosen_from_;
  if (!slot_freed_.empty()) {
    since = slot_freed_.front().second;
    slot_freed_.erase(slot_freed_.begin());
  }
  metrics_.SchedulingOverhead(SecondsSince(since));
}

void ServiceRunSource::Ended(const WorkerEnding& ending) {
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
  } else if (draining_ || InterruptionGuard::Interrupted() || run.view.attempt < max_attempts_) {
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

void ServiceRunSource::EndTurn() {
  const std::vector<SweepEntry*> done = sweeps_.Select(
      [](const SweepEntry& entry) { return entry.active && entry.pending.empty() && entry.running == 0; });
  for (SweepEntry* entry : done) {
    const bool cancelled = entry->sweep.cancel_requested;
    FinishSweep(sweeps_, *entry, cancelled ? QueuedSweepState::kCancelled : QueuedSweepState::kOk,
                cancelled ? "cancelled; finished results kept" : "");
  }
}

void ServiceRunSource::Draining() {
  if (InterruptionGuard::Interrupted() && !draining_) {
    spdlog::info("{} received: draining (no new runs; running ones may finish for {:g} s)",
                 InterruptionGuard::Signal() == SIGTERM ? "SIGTERM" : "signal", drain_grace_s_);
  }
  draining_ = true;
}

void ServiceRunSource::Terminating(std::size_t running) {
  spdlog::warn("drain grace period over: stopping {} running runs; they are queued again", running);
}

}  // namespace slamsweep::orchestrator::service
