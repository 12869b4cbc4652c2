#include "orchestrator/sweep/sweep_runner.h"

#include <algorithm>
#include <optional>
#include <set>

#include "orchestrator/phase_times/phase_times.h"
#include "orchestrator/store/named_study.h"
#include "orchestrator/store/results_store.h"
#include "orchestrator/supervisor/supervisor.h"
#include "orchestrator/sweep/output_lock.h"
#include "orchestrator/sweep/sweep_run_source.h"
#include "orchestrator/sweep/sweep_steps.h"

namespace slamsweep::orchestrator::inline sweep {
namespace {

std::string ExpectationKey(const RunSpec& run) { return run.algorithm.name + "\t" + run.sequence.entry.name; }

bool IsDone(std::optional<RunStatus> status, bool rerun_failed) {
  return status == RunStatus::kOk || (status == RunStatus::kFailed && !rerun_failed);
}

}  // namespace

bool RecordedRunIsReusable(const RunSpec& run, std::optional<RunStatus> recorded_status,
                           const nlohmann::json& recorded_spec, const SweepSettings& settings, bool& stale) {
  stale = false;
  if (!IsDone(recorded_status, settings.rerun_failed)) return false;
  const auto build = recorded_spec.find("build");
  const auto evaluation = recorded_spec.find("evaluation");
  nlohmann::json current = ToJson(run);
  // The reference map is scoring like `evaluation` (left out of the run id): another one changes the map scores.
  const auto sequence = recorded_spec.find("sequence");
  const std::string recorded_reference_map =
      sequence != recorded_spec.end() && sequence->is_object() ? sequence->value("reference_map", "") : "";
  stale = build == recorded_spec.end() || *build != current["build"] || evaluation == recorded_spec.end() ||
          !SameEvaluation(*evaluation, run.evaluation) ||
          recorded_reference_map != run.sequence.entry.reference_map_path;
  return !stale || settings.reuse_stale;
}

int SweepOutcome::ExitCode() const {
  if (interrupted) return 130;
  return failed > 0 || not_started > 0 ? 1 : 0;
}

std::vector<const RunSpec*> LongestExpectedFirst(const std::vector<const RunSpec*>& runs,
                                                 const std::map<std::string, double>& typical_wall_s) {
  double longest_known = 0.0;
  for (const auto& [key, seconds] : typical_wall_s) longest_known = std::max(longest_known, seconds);
  auto expected = [&](const RunSpec* run) {
    const auto found = typical_wall_s.find(ExpectationKey(*run));
    // Unknown runs first: the one that turns out long must not be the last to start.
    return found == typical_wall_s.end() ? longest_known + 1.0 : found->second;
  };
  std::vector<const RunSpec*> ordered = runs;
  std::stable_sort(ordered.begin(), ordered.end(),
                   [&](const RunSpec* a, const RunSpec* b) { return expected(a) > expected(b); });
  return ordered;
}

SweepOutcome RunSweep(const std::vector<RunSpec>& runs, const SweepSettings& settings, Executor& executor,
                      Status& status) {
  std::optional<PhaseTimer> phase(std::in_place, "to_do");
  OutputLock lock(settings.output_dir);
  ResultsStore store = ResultsStore::Open(settings.output_dir / "results.sqlite");
  if (!settings.validity_study.empty()) WriteNamedStudy(ReadNamedStudy(settings.validity_study), settings.output_dir);

  SweepOutcome outcome;
  outcome.total = runs.size();
  const std::int64_t sweep_id = store.BeginSweep(SweepInfoFor(settings));
  const std::vector<const RunSpec*> to_run = RunsStillToDo(runs, settings, store, sweep_id, outcome);
  phase.reset();
  status.Planned(to_run.size(), outcome.already_done);

  SweepRunSource source(settings, status, store, sweep_id, outcome);
  for (const RunSpec* run : LongestExpectedFirst(to_run, store.TypicalWallSeconds())) source.Add(run);
  Supervisor(executor, {.jobs = settings.jobs, .drain_grace_s = 0.0, .time_phases = true}).Run(source);
  source.CountNotStarted();
  status.Done();

  // The whole matrix, including runs finished by earlier sweeps, decides the summary and the exit code.
  std::set<std::string> matrix_ids;
  for (const RunSpec& run : runs) matrix_ids.insert(run.run_id);
  phase.emplace("summary");
  const std::size_t failed_in_store = WriteSweepOutputs(store, matrix_ids, settings.output_dir);
  outcome.failed = std::max(outcome.failed, failed_in_store);
  store.FinishSweep(sweep_id,
                    outcome.interrupted       ? SweepStatus::kInterrupted
                    : outcome.ExitCode() == 0 ? SweepStatus::kOk
                                              : SweepStatus::kFailed,
                    static_cast<std::int64_t>(outcome.ok + outcome.failed));
  phase.reset();
  FlushPhaseTimes("sweep");
  return outcome;
}

}  // namespace slamsweep::orchestrator::inline sweep
