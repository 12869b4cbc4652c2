#include "orchestrator/service/sweep_table.h"

#include <chrono>

#include <spdlog/spdlog.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/store/results_store.h"
#include "orchestrator/run/run_json.h"

namespace slamsweep::orchestrator::service {

SweepTable::SweepTable(QueueStore& queue, std::mutex& queue_mutex, std::filesystem::path sweeps_root, std::size_t slots)
    : queue_(queue), queue_mutex_(queue_mutex), sweeps_root_(std::move(sweeps_root)), slots_(slots) {}

SweepTable::~SweepTable() = default;

void SweepTable::Load() {
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
    if (IsFinished(sweep.state)) {
      const bool has_report = std::filesystem::exists(sweep.result_dir / "report" / "index.html");
      entry->report = has_report ? ReportState::kReady : ReportState::kWriting;
      if (!has_report) report_jobs_.push_back(sweep.id);
    }
    entry->sweep = std::move(sweep);
    const std::lock_guard lock(mutex_);
    sweeps_[entry->sweep.id] = std::move(entry);
  }
}

QueuedSweep SweepTable::Add(QueuedSweep sweep, const std::vector<RunSpec>& runs) {
  std::vector<nlohmann::json> specs;
  specs.reserve(runs.size());
  for (const RunSpec& run : runs) specs.push_back(ToJson(run));
  {
    const std::lock_guard lock(queue_mutex_);
    sweep = queue_.AddSweep(std::move(sweep), specs, sweeps_root_);
  }
  auto entry = std::make_unique<SweepEntry>();
  entry->sweep = sweep;
  for (const RunSpec& run : runs) {
    entry->by_run_id[run.run_id] = entry->runs.size();
    entry->runs.push_back({run, {run.run_id, QueuedRunState::kQueued, 0, std::nullopt, std::nullopt, ""}, false});
  }
  const std::lock_guard lock(mutex_);
  sweeps_[sweep.id] = std::move(entry);
  return sweep;
}

CancelOutcome SweepTable::RequestCancel(std::int64_t sweep_id) {
  {
    const std::lock_guard lock(mutex_);
    const auto found = sweeps_.find(sweep_id);
    if (found == sweeps_.end()) return {};
    SweepEntry& entry = *found->second;
    if (IsFinished(entry.sweep.state)) return {true, entry.sweep.state};
    entry.sweep.cancel_requested = true;
  }
  const std::lock_guard lock(queue_mutex_);
  queue_.RequestCancel(sweep_id);
  return {true, std::nullopt};
}

std::vector<SweepView> SweepTable::Sweeps() const {
  const std::lock_guard lock(mutex_);
  std::vector<SweepView> views;
  views.reserve(sweeps_.size());
  for (const auto& [id, entry] : sweeps_)
    views.push_back(SweepViewOf(*entry, slots_, std::chrono::steady_clock::now()));
  return views;
}

std::optional<SweepView> SweepTable::Sweep(std::int64_t id) const {
  const std::lock_guard lock(mutex_);
  const auto found = sweeps_.find(id);
  if (found == sweeps_.end()) return std::nullopt;
  return SweepViewOf(*found->second, slots_, std::chrono::steady_clock::now());
}

std::optional<std::vector<RunView>> SweepTable::Runs(std::int64_t sweep_id) const {
  const std::lock_guard lock(mutex_);
  const auto found = sweeps_.find(sweep_id);
  if (found == sweeps_.end()) return std::nullopt;
  return RunViewsOf(*found->second);
}

std::size_t SweepTable::UnfinishedSweeps() const {
  const std::lock_guard lock(mutex_);
  std::size_t unfinished = 0;
  for (const auto& [id, entry] : sweeps_) unfinished += IsFinished(entry->sweep.state) ? 0 : 1;
  return unfinished;
}

std::optional<QueuedSweep> SweepTable::TakeReportJob() {
  const std::lock_guard lock(mutex_);
  if (report_jobs_.empty()) return std::nullopt;
  const std::int64_t id = report_jobs_.front();
  report_jobs_.pop_front();
  return sweeps_.at(id)->sweep;
}

void SweepTable::ReportWritten(std::int64_t sweep_id, bool ok) {
  const std::lock_guard lock(mutex_);
  sweeps_.at(sweep_id)->report = ok ? ReportState::kReady : ReportState::kFailed;
}

std::vector<SweepEntry*> SweepTable::Select(const std::function<bool(const SweepEntry&)>& wanted) {
  std::vector<SweepEntry*> selected;
  const std::lock_guard lock(mutex_);
  for (auto& [id, entry] : sweeps_) {
    if (wanted(*entry)) selected.push_back(entry.get());
  }
  return selected;
}

SweepEntry& SweepTable::Entry(std::int64_t id) {
  const std::lock_guard lock(mutex_);
  return *sweeps_.at(id);
}

std::optional<std::filesystem::path> SweepTable::ResultDir(std::int64_t id) const {
  const std::lock_guard lock(mutex_);
  const auto found = sweeps_.find(id);
  if (found == sweeps_.end()) return std::nullopt;
  return found->second->sweep.result_dir;
}

std::vector<std::int64_t> SweepTable::SweepsWithOkRun(const std::string& run_id, std::int64_t except_sweep) const {
  const std::lock_guard lock(queue_mutex_);
  return queue_.SweepsWithOkRun(run_id, except_sweep);
}

void SweepTable::SetRunState(SweepEntry& entry, std::size_t index, QueuedRunState state, bool attempt_started,
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

void SweepTable::MarkStarted(SweepEntry& entry) {
  if (entry.sweep.state == QueuedSweepState::kQueued) {
    const std::lock_guard lock(queue_mutex_);
    queue_.SetSweepState(entry.sweep.id, QueuedSweepState::kRunning);
  }
  const std::lock_guard lock(mutex_);
  entry.active = true;
  entry.activated_at = std::chrono::steady_clock::now();
  entry.sweep.state = QueuedSweepState::kRunning;
  if (entry.sweep.started_at.empty()) entry.sweep.started_at = UtcNowIso8601();
}

void SweepTable::RecordEnded(const SweepEntry& entry, QueuedSweepState state, const std::string& message) {
  const std::lock_guard lock(queue_mutex_);
  queue_.SetSweepState(entry.sweep.id, state, message);
}

void SweepTable::ShowEnded(SweepEntry& entry, QueuedSweepState state, const std::string& message, ReportState report) {
  const std::lock_guard lock(mutex_);
  entry.active = false;
  entry.sweep.state = state;
  entry.sweep.message = message;
  entry.sweep.finished_at = UtcNowIso8601();
  entry.report = report;
  if (report == ReportState::kWriting) report_jobs_.push_back(entry.sweep.id);
}

void SweepTable::CountFinished(SweepEntry& entry) {
  const std::lock_guard lock(mutex_);
  ++entry.finished_here;
}

void SweepTable::CloseAll() {
  const std::lock_guard lock(mutex_);
  for (auto& [id, entry] : sweeps_) {
    entry->store.reset();
    entry->lock.reset();
    entry->active = false;
  }
}

}  // namespace slamsweep::orchestrator::service
