#include "orchestrator/sweep/sweep_run_source.h"

#include <fmt/format.h>

#include "orchestrator/phase_times/phase_times.h"
#include "orchestrator/run/run_folder.h"
#include "orchestrator/sweep/sweep_steps.h"

namespace slamsweep::orchestrator::inline sweep {

SweepRunSource::SweepRunSource(const SweepSettings& settings, Status& status, ResultsStore& store,
                               std::int64_t sweep_id, SweepOutcome& outcome)
    : settings_(settings), status_(status), store_(store), sweep_id_(sweep_id), outcome_(outcome) {}

void SweepRunSource::Add(const RunSpec* run) {
  queue_.push_back(run);
  by_id_[run->run_id] = run;
}

std::optional<RunStart> SweepRunSource::Next() {
  if (queue_.empty() || BudgetExhausted()) return std::nullopt;
  const PhaseTimer phase("run_folder");
  const RunSpec& run = *queue_.front();
  queue_.pop_front();
  return RunStart{&run, PrepareRunFolder(settings_.output_dir, run)};
}

void SweepRunSource::Started(const RunStart& start) {
  const PhaseTimer phase("status");
  status_.Started(start.run->run_id);
}

void SweepRunSource::Ended(const WorkerEnding& ending) {
  const auto found = by_id_.find(ending.run_id);
  if (found == by_id_.end()) return;
  std::optional<FinishedRun> finished;
  {
    const PhaseTimer phase("record");
    finished = RecordWorkerEnding(*found->second, ending, settings_.output_dir, store_, sweep_id_);
  }
  const PhaseTimer phase("status");
  if (!finished) {
    ++outcome_.not_started;
    return;
  }
  shared_files_.Share(RunFolder(settings_.output_dir, ending.run_id) / "reference.tum");
  if (finished->ok) {
    ++outcome_.ok;
  } else {
    ++outcome_.failed;
    ++failures_;
  }
  status_.Finished(*finished);
}

void SweepRunSource::Draining() {
  outcome_.interrupted = true;
  status_.Message("interrupted: stopping running runs; finished results are kept");
}

void SweepRunSource::CountNotStarted() {
  outcome_.not_started += queue_.size();
  if (!queue_.empty() && !outcome_.interrupted) {
    status_.Message(
        fmt::format("failure budget of {} exhausted: {} runs not started", settings_.failure_budget, queue_.size()));
  }
}

}  // namespace slamsweep::orchestrator::inline sweep
