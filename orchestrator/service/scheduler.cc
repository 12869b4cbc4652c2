#include "orchestrator/service/scheduler.h"

#include <algorithm>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/process/interruption.h"
#include "orchestrator/matrix/run_id.h"
#include "orchestrator/process/wake_up.h"
#include "orchestrator/service/run_reuse.h"
#include "orchestrator/run/run_folder.h"
#include "orchestrator/sweep/status.h"
#include "orchestrator/sweep/sweep_steps.h"

namespace slamsweep::orchestrator::service {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

bool IsFinishedSweepState(const std::string& state) {
  return state == "ok" || state == "failed" || state == "cancelled";
}

RunCounts Count(const std::vector<RunView>& runs) {
  RunCounts counts;
  counts.total = runs.size();
  for (const RunView& run : runs) {
    if (run.state == "queued") ++counts.queued;
    if (run.state == "running") ++counts.running;
    if (run.state == "ok") ++counts.ok;
    if (run.state == "failed") ++counts.failed;
    if (run.state == "reused") ++counts.reused;
    if (run.state == "cancelled") ++counts.cancelled;
  }
  return counts;
}

}  // namespace

Scheduler::Scheduler(QueueStore& queue, std::mutex& queue_mutex, const std::filesystem::path& data_dir,
                     SchedulerOptions options, ServiceMetrics& metrics)
    : queue_(queue), queue_mutex_(queue_mutex), data_dir_(data_dir), options_(options), metrics_(metrics) {}

Scheduler::~Scheduler() = default;

void Scheduler::Notify() { RequestWakeUp(); }

void Scheduler::Recover() {
  std::vector<QueuedSweep> sweeps;
  {
    const std::lock_guard lock(queue_mutex_);
    const std::size_t requeued = queue_.RequeueRunning();
    if (requeued > 0) spdlog::info("{} runs left running by the previous server are queued again", requeued);
    sweeps = queue_.Sweeps();
  }
  for (QueuedSweep& sweep : sweeps) {
    auto entry = std::make_unique<SweepEntry>();
    std::vector<QueuedRun> runs;
    {
      const std::lock_guard lock(queue_mutex_);
      runs = queue_.Runs(sweep.id);
    }
    for (QueuedRun& run : runs) {
      RunEntry run_entry;
      try {
        run_entry.spec = RunSpecFromJson(run.spec);
      } catch (const evaluator::InputError& error) {
        spdlog::error("sweep {}: run {}: unreadable planned run.json: {}", sweep.id, run.run_id, error.what());
        continue;
      }
      run_entry.view = {run.run_id, run.state, run.attempt, run.reused_from, run.wall_s, run.reason};
      entry->by_run_id[run.run_id] = entry->runs.size();
      entry->runs.push_back(std::move(run_entry));
    }
    if (IsFinishedSweepState(sweep.state)) {
      const bool has_report = std::filesystem::exists(sweep.result_dir / "report" / "index.html");
      entry->report = has_report ? "ready" : "writing";
      if (!has_report) report_jobs_.push_back(sweep.id);
    }
    entry->sweep = std::move(sweep);
    const std::lock_guard lock(mutex_);
    sweeps_[entry->sweep.id] = std::move(entry);
  }
}

QueuedSweep Scheduler::Submit(QueuedSweep sweep, const std::vector<RunSpec>& runs) {
  std::vector<nlohmann::json> specs;
  specs.reserve(runs.size());
  for (const RunSpec& run : runs) specs.push_back(ToJson(run));
  {
    const std::lock_guard lock(queue_mutex_);
    sweep = queue_.AddSweep(std::move(sweep), specs, data_dir_ / "sweeps");
  }
  auto entry = std::make_unique<SweepEntry>();
  entry->sweep = sweep;
  for (const RunSpec& run : runs) {
    entry->by_run_id[run.run_id] = entry->runs.size();
    entry->runs.push_back({run, {run.run_id, "queued", 0, std::nullopt, std::nullopt, ""}, false});
  }
  {
    const std::lock_guard lock(mutex_);
    sweeps_[sweep.id] = std::move(entry);
  }
  spdlog::info("sweep {} '{}' submitted by {}: {} runs, priority {}", sweep.id, sweep.name, sweep.submitter,
               runs.size(), sweep.priority);
  Notify();
  return sweep;
}

bool Scheduler::Cancel(std::int64_t sweep_id, std::string& state_after) {
  {
    const std::lock_guard lock(mutex_);
    const auto found = sweeps_.find(sweep_id);
    if (found == sweeps_.end()) return false;
    SweepEntry& entry = *found->second;
    if (IsFinishedSweepState(entry.sweep.state)) {
      state_after = entry.sweep.state;
      return true;
    }
    entry.sweep.cancel_requested = true;
    state_after = "cancelling";
  }
  {
    const std::lock_guard lock(queue_mutex_);
    queue_.RequestCancel(sweep_id);
  }
  spdlog::info("sweep {}: cancel requested", sweep_id);
  Notify();
  return true;
}

void Scheduler::Drain() {
  draining_ = true;
  Notify();
}

SweepView Scheduler::ViewOf(const SweepEntry& entry) const {
  SweepView view;
  view.sweep = entry.sweep;
  view.sweep.config_text.clear();  // large, and the API has no use for it
  std::vector<RunView> runs;
  runs.reserve(entry.runs.size());
  for (const RunEntry& run : entry.runs) runs.push_back(run.view);
  view.counts = Count(runs);
  view.report = entry.report;
  if (entry.active) {
    view.eta = EstimateRemaining(entry.finished_here, entry.finished_here + view.counts.queued + view.counts.running,
                                 options_.jobs, Clock::now() - entry.activated_at);
  }
  return view;
}

std::vector<SweepView> Scheduler::Sweeps() const {
  const std::lock_guard lock(mutex_);
  std::vector<SweepView> views;
  views.reserve(sweeps_.size());
  for (const auto& [id, entry] : sweeps_) views.push_back(ViewOf(*entry));
  return views;
}

std::optional<SweepView> Scheduler::Sweep(std::int64_t id) const {
  const std::lock_guard lock(mutex_);
  const auto found = sweeps_.find(id);
  if (found == sweeps_.end()) return std::nullopt;
  return ViewOf(*found->second);
}

std::optional<std::vector<RunView>> Scheduler::Runs(std::int64_t sweep_id) const {
  const std::lock_guard lock(mutex_);
  const auto found = sweeps_.find(sweep_id);
  if (found == sweeps_.end()) return std::nullopt;
  std::vector<RunView> runs;
  for (const RunEntry& run : found->second->runs) runs.push_back(run.view);
  return runs;
}

std::size_t Scheduler::UnfinishedSweeps() const {
  const std::lock_guard lock(mutex_);
  std::size_t unfinished = 0;
  for (const auto& [id, entry] : sweeps_) unfinished += IsFinishedSweepState(entry->sweep.state) ? 0 : 1;
  return unfinished;
}

std::optional<QueuedSweep> Scheduler::TakeReportJob() {
  const std::lock_guard lock(mutex_);
  if (report_jobs_.empty()) return std::nullopt;
  const std::int64_t id = report_jobs_.front();
  report_jobs_.pop_front();
  return sweeps_.at(id)->sweep;
}

void Scheduler::ReportWritten(std::int64_t sweep_id, bool ok) {
  const std::lock_guard lock(mutex_);
  sweeps_.at(sweep_id)->report = ok ? "ready" : "failed";
}

void Scheduler::SetRunState(SweepEntry& entry, std::size_t index, const std::string& state, bool attempt_started,
                            std::optional<double> wall_s, const std::string& reason,
                            std::optional<std::int64_t> reused_from) {
  RunEntry& run = entry.runs[index];
  {
    const std::lock_guard lock(queue_mutex_);
    queue_.SetRunState(entry.sweep.id, run.view.run_id, state, attempt_started, wall_s, reason, reused_from);
  }
  const std::lock_guard lock(mutex_);
  run.view.state = state;
  if (attempt_started) ++run.view.attempt;
  run.view.wall_s = wall_s;
  run.view.reason = reason;
  run.view.reused_from = reused_from;
}

bool Scheduler::Activate(SweepEntry& entry) {
  // The sweep's result directory, opened as `slamsweep run` opens its output directory.
  SweepSettings settings;
  settings.name = entry.sweep.name;
  settings.output_dir = entry.sweep.result_dir;
  settings.config_path = entry.sweep.config_name;
  settings.config_sha = fmt::format("{:016x}", Fnv1a64(entry.sweep.config_text));
  settings.command_line =
      fmt::format("slamsweep submit {} (sweep {} of the service in {}, by {})", entry.sweep.config_name, entry.sweep.id,
                  data_dir_.string(), entry.sweep.submitter);
  try {
    entry.lock = std::make_unique<OutputLock>(settings.output_dir);
    entry.store.emplace(ResultsStore::Open(settings.output_dir / "results.sqlite"));
    entry.store_sweep_id = entry.store->BeginSweep(SweepInfoFor(settings));
    // Runs the result directory already holds (a server killed after recording them, before its queue
    // said so) count as done: the rerun-skip check of `slamsweep run`, adoption included.
    std::vector<RunSpec> unfinished;
    for (const RunEntry& run : entry.runs) {
      if (run.view.state == "queued" || run.view.state == "running") unfinished.push_back(run.spec);
    }
    SweepOutcome ignored;
    const std::vector<const RunSpec*> to_do =
        RunsStillToDo(unfinished, settings, *entry.store, entry.store_sweep_id, ignored);
    std::set<std::string> to_do_ids;
    for (const RunSpec* run : to_do) to_do_ids.insert(run->run_id);
    for (std::size_t i = 0; i < entry.runs.size(); ++i) {
      RunEntry& run = entry.runs[i];
      if (run.view.state != "queued" && run.view.state != "running") continue;
      if (to_do_ids.count(run.view.run_id) > 0) {
        entry.pending.push_back(i);
        continue;
      }
      const std::optional<RunRecord> stored = entry.store->FindRun(run.view.run_id);
      const std::string state = stored && stored->status == RunStatus::kOk ? "ok" : "failed";
      SetRunState(entry, i, state, false, stored ? stored->wall_s : std::nullopt,
                  stored ? stored->result.value("reason", "") : "");
    }
  } catch (const std::exception& error) {
    entry.lock.reset();
    entry.store.reset();
    Fail(entry, fmt::format("cannot open the result directory {}: {}", settings.output_dir.string(), error.what()));
    return false;
  }
  if (entry.sweep.state == "queued") {
    const std::lock_guard lock(queue_mutex_);
    queue_.SetSweepState(entry.sweep.id, "running");
  }
  const std::lock_guard lock(mutex_);
  entry.active = true;
  entry.activated_at = Clock::now();
  entry.sweep.state = "running";
  if (entry.sweep.started_at.empty()) entry.sweep.started_at = UtcNowIso8601();
  return true;
}

void Scheduler::ActivateWaitingSweeps() {
  std::vector<SweepEntry*> waiting;
  {
    const std::lock_guard lock(mutex_);
    for (auto& [id, entry] : sweeps_) {
      if (!entry->active && !IsFinishedSweepState(entry->sweep.state)) waiting.push_back(entry.get());
    }
  }
  for (SweepEntry* entry : waiting) Activate(*entry);
}

void Scheduler::HandleCancels(Executor& executor) {
  std::vector<SweepEntry*> cancelled;
  {
    const std::lock_guard lock(mutex_);
    for (auto& [id, entry] : sweeps_) {
      if (entry->active && entry->sweep.cancel_requested) cancelled.push_back(entry.get());
    }
  }
  for (SweepEntry* entry : cancelled) {
    for (const std::size_t index : entry->pending)
      SetRunState(*entry, index, "cancelled", false, std::nullopt, "sweep cancelled");
    entry->pending.clear();
    for (RunEntry& run : entry->runs) {
      if (run.view.state != "running" || run.stop_sent) continue;
      executor.Stop(run.view.run_id);
      run.stop_sent = true;
    }
  }
}

Scheduler::SweepEntry* Scheduler::PickSweep() {
  // Snapshot of the candidates; only this thread changes pending/running.
  std::vector<SweepEntry*> candidates;
  {
    const std::lock_guard lock(mutex_);
    for (auto& [id, entry] : sweeps_) {
      if (entry->active && !entry->sweep.cancel_requested && !entry->pending.empty()) candidates.push_back(entry.get());
    }
  }
  SweepEntry* best = nullptr;
  for (SweepEntry* entry : candidates) {
    // A sweep whose every pending run waits for its running twin elsewhere cannot start anything now.
    const bool startable = std::any_of(entry->pending.begin(), entry->pending.end(), [&](std::size_t index) {
      return running_.count(entry->runs[index].view.run_id) == 0;
    });
    if (!startable) continue;
    if (best == nullptr) {
      best = entry;
      continue;
    }
    const auto key = [](const SweepEntry* e) {
      return std::make_tuple(-e->sweep.priority, e->running, e->last_start_tick, e->sweep.id);
    };
    if (key(entry) < key(best)) best = entry;
  }
  return best;
}

bool Scheduler::TryReuse(SweepEntry& entry, std::size_t index) {
  RunEntry& run = entry.runs[index];
  std::vector<std::int64_t> sources;
  {
    const std::lock_guard lock(queue_mutex_);
    sources = queue_.SweepsWithOkRun(run.view.run_id, entry.sweep.id);
  }
  for (const std::int64_t source_id : sources) {
    std::filesystem::path source_dir;
    {
      const std::lock_guard lock(mutex_);
      const auto found = sweeps_.find(source_id);
      if (found == sweeps_.end()) continue;
      source_dir = found->second->sweep.result_dir;
    }
    try {
      const std::optional<nlohmann::json> result = ReusableResult(run.spec, source_dir);
      if (!result) continue;
      LinkRunFolder(run.spec, source_dir, entry.sweep.result_dir);
      entry.store->RecordRun(entry.store_sweep_id, ToJson(run.spec), *result,
                             std::filesystem::path("runs") / run.view.run_id);
      std::optional<double> wall_s;
      if (result->contains("wall_s") && (*result)["wall_s"].is_number()) wall_s = (*result)["wall_s"].get<double>();
      SetRunState(entry, index, "reused", false, wall_s, "", source_id);
      metrics_.RunFinished("reused", 0.0, false);
      spdlog::info("sweep {}: {} reused from sweep {}", entry.sweep.id, run.view.run_id, source_id);
      return true;
    } catch (const std::exception& error) {
      spdlog::warn("sweep {}: {} not reused from sweep {}: {}", entry.sweep.id, run.view.run_id, source_id,
                   error.what());
    }
  }
  return false;
}

void Scheduler::StartRun(Executor& executor, SweepEntry& entry, std::size_t index) {
  RunEntry& run = entry.runs[index];
  const std::filesystem::path run_dir = PrepareRunFolder(entry.sweep.result_dir, run.spec);
  SetRunState(entry, index, "running", true, std::nullopt, "");
  executor.Start(run.spec, run_dir);
  running_[run.view.run_id] = entry.sweep.id;
  ++entry.running;
  entry.last_start_tick = ++tick_;
}

void Scheduler::StartRuns(Executor& executor) {
  if (draining_ || InterruptionGuard::Interrupted()) return;
  while (executor.Running() < options_.jobs) {
    const auto started = Clock::now();
    SweepEntry* entry = PickSweep();
    if (entry == nullptr) {
      slot_freed_.clear();  // nothing waited for those slots: no scheduling latency to count
      return;
    }
    // The sweep's first run that does not wait for a running twin.
    auto position = std::find_if(entry->pending.begin(), entry->pending.end(), [&](std::size_t index) {
      return running_.count(entry->runs[index].view.run_id) == 0;
    });
    const std::size_t index = *position;
    entry->pending.erase(position);
    if (TryReuse(*entry, index)) {
      const std::lock_guard lock(mutex_);
      ++entry->finished_here;
      continue;
    }
    try {
      StartRun(executor, *entry, index);
    } catch (const std::exception& error) {
      // The run's folder could not be prepared (disk full, permissions): a failed run, as a worker
      // that cannot start is one; the sweep goes on.
      const nlohmann::json result = MissingResult(entry->runs[index].spec, error.what(), false);
      try {
        entry->store->RecordRun(entry->store_sweep_id, ToJson(entry->runs[index].spec), result,
                                std::filesystem::path("runs") / entry->runs[index].view.run_id);
      } catch (const std::exception& store_error) {
        spdlog::error("sweep {}: cannot record {}: {}", entry->sweep.id, entry->runs[index].view.run_id,
                      store_error.what());
      }
      SetRunState(*entry, index, "failed", false, std::nullopt, std::string("internal: ") + error.what());
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
  SweepEntry* entry = nullptr;
  {
    const std::lock_guard lock(mutex_);
    entry = sweeps_.at(sweep_id).get();
  }
  const std::size_t index = entry->by_run_id.at(ending.run_id);
  RunEntry& run = entry->runs[index];
  --entry->running;
  run.stop_sent = false;
  std::optional<FinishedRun> finished;
  try {
    finished = RecordWorkerEnding(run.spec, ending, entry->sweep.result_dir, *entry->store, entry->store_sweep_id);
  } catch (const std::exception& error) {
    spdlog::error("sweep {}: cannot record {}: {}", sweep_id, ending.run_id, error.what());
    finished = FinishedRun{ending.run_id, false, std::string("internal: ") + error.what(), 0.0};
  }
  if (finished) {
    SetRunState(*entry, index, finished->ok ? "ok" : "failed", false,
                finished->wall_s > 0 ? std::optional<double>(finished->wall_s) : std::nullopt, finished->reason);
    metrics_.RunFinished(finished->ok ? "ok" : "failed", finished->wall_s, true);
    const std::lock_guard lock(mutex_);
    ++entry->finished_here;
  } else if (entry->sweep.cancel_requested) {
    SetRunState(*entry, index, "cancelled", false, std::nullopt, "sweep cancelled: " + ending.reason);
  } else if (draining_ || InterruptionGuard::Interrupted() || run.view.attempt < options_.max_attempts) {
    // Stopped by a drain (or killed from outside): it runs again, from scratch, when the server resumes.
    SetRunState(*entry, index, "queued", false, std::nullopt, "");
    entry->pending.push_front(index);
  } else {
    const nlohmann::json result =
        MissingResult(run.spec, fmt::format("{} ({} attempts interrupted)", ending.reason, run.view.attempt), true);
    WriteJsonAtomically(RunFolder(entry->sweep.result_dir, run.spec.run_id) / "result.json", result);
    entry->store->RecordRun(entry->store_sweep_id, ToJson(run.spec), result,
                            std::filesystem::path("runs") / run.spec.run_id);
    SetRunState(*entry, index, "failed", false, std::nullopt, result.value("reason", ""));
    metrics_.RunFinished("failed", 0.0, false);
  }
  // The scheduling latency of the run that takes this slot counts from here, recording included.
  slot_freed_.emplace_back(ending.run_id, started);
}

void Scheduler::Fail(SweepEntry& entry, const std::string& message) {
  spdlog::error("sweep {}: {}", entry.sweep.id, message);
  for (std::size_t i = 0; i < entry.runs.size(); ++i) {
    if (entry.runs[i].view.state == "queued") SetRunState(entry, i, "cancelled", false, std::nullopt, message);
  }
  entry.pending.clear();
  {
    const std::lock_guard lock(queue_mutex_);
    queue_.SetSweepState(entry.sweep.id, "failed", message);
  }
  const std::lock_guard lock(mutex_);
  entry.active = false;
  entry.sweep.state = "failed";
  entry.sweep.message = message;
  entry.sweep.finished_at = UtcNowIso8601();
  entry.report = "failed";
}

void Scheduler::Finish(SweepEntry& entry, const std::string& state, const std::string& message) {
  std::set<std::string> matrix_ids;
  std::size_t ran = 0;
  for (const RunEntry& run : entry.runs) {
    if (run.view.state != "cancelled") matrix_ids.insert(run.view.run_id);
    ran += run.view.state == "ok" || run.view.state == "failed" ? 1 : 0;
  }
  std::string final_state = state;
  try {
    const std::size_t failed = WriteSweepOutputs(*entry.store, matrix_ids, entry.sweep.result_dir);
    if (final_state != "cancelled") final_state = failed > 0 ? "failed" : "ok";
    entry.store->FinishSweep(entry.store_sweep_id,
                             final_state == "cancelled" ? SweepStatus::kInterrupted
                             : failed > 0               ? SweepStatus::kFailed
                                                        : SweepStatus::kOk,
                             static_cast<std::int64_t>(ran));
  } catch (const std::exception& error) {
    entry.store.reset();
    entry.lock.reset();
    Fail(entry, fmt::format("cannot write the results into {}: {}", entry.sweep.result_dir.string(), error.what()));
    return;
  }
  entry.store.reset();
  entry.lock.reset();
  {
    const std::lock_guard lock(queue_mutex_);
    queue_.SetSweepState(entry.sweep.id, final_state, message);
  }
  spdlog::info("sweep {} '{}' finished: {}", entry.sweep.id, entry.sweep.name, final_state);
  const std::lock_guard lock(mutex_);
  entry.active = false;
  entry.sweep.state = final_state;
  entry.sweep.message = message;
  entry.sweep.finished_at = UtcNowIso8601();
  entry.report = "writing";
  report_jobs_.push_back(entry.sweep.id);
}

void Scheduler::FinishSweeps() {
  std::vector<SweepEntry*> done;
  {
    const std::lock_guard lock(mutex_);
    for (auto& [id, entry] : sweeps_) {
      if (entry->active && entry->pending.empty() && entry->running == 0) done.push_back(entry.get());
    }
  }
  for (SweepEntry* entry : done) {
    const bool cancelled = entry->sweep.cancel_requested;
    Finish(*entry, cancelled ? "cancelled" : "ok", cancelled ? "cancelled; finished results kept" : "");
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
  // Sweeps still unfinished stay "running" in the queue; the next server resumes them.
  const std::lock_guard lock(mutex_);
  for (auto& [id, entry] : sweeps_) {
    entry->store.reset();
    entry->lock.reset();
    entry->active = false;
  }
}

}  // namespace slamsweep::orchestrator::service
