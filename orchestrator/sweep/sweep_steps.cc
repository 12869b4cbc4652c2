#include "orchestrator/sweep/sweep_steps.h"

#include <unistd.h>

#include <optional>

#include "orchestrator/phase_times/phase_times.h"
#include "orchestrator/store/result_files.h"
#include "orchestrator/run/run_folder.h"
#include "orchestrator/run/run_json.h"

namespace slamsweep::orchestrator::inline sweep {
namespace {

std::string HostName() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

// A finished run reused under another build or evaluation (--reuse-stale) carries the "stale" mark in its
// folder's result.json, which the report reads, and in the store, which the summaries read.
void MarkStale(const std::filesystem::path& output_dir, const std::string& run_id, ResultsStore& store) {
  const std::filesystem::path run_dir = RunFolder(output_dir, run_id);
  StoredResult stored = ReadRunResult(run_dir);
  const RunFlags stale{RunFlag::kStale};
  if (stored.result) {
    RunFlags flags = RunFlagsOf(ReadRunSpecJson(run_dir).value_or(nlohmann::json()), *stored.result);
    if (!flags.Has(RunFlag::kStale)) {
      flags |= stale;
      (*stored.result)["flags"] = ToJson(flags);
      WriteJsonAtomically(run_dir / "result.json", *stored.result);
    }
  }
  store.AddRunFlags(run_id, stale);
}

}  // namespace

std::vector<const RunSpec*> RunsStillToDo(const std::vector<RunSpec>& runs, const SweepSettings& settings,
                                          ResultsStore& store, std::int64_t sweep_id, SweepOutcome& outcome) {
  std::vector<const RunSpec*> to_run;
  for (const RunSpec& run : runs) {
    bool stale = false;
    const std::optional<RunRecord> recorded = store.FindRun(run.run_id);
    if (recorded) {
      const bool reusable = RecordedRunIsReusable(run, recorded->status, recorded->run_spec, settings, stale);
      outcome.stale += stale ? 1 : 0;
      if (reusable) {
        if (stale) MarkStale(settings.output_dir, run.run_id, store);
        ++outcome.already_done;
        continue;
      }
    } else {
      // A result.json the store never saw: the orchestrator died between the worker's rename and
      // the store's commit. Adopting it keeps "kill -9, run again" from repeating finished work.
      const std::filesystem::path run_dir = RunFolder(settings.output_dir, run.run_id);
      StoredResult stored = ReadRunResult(run_dir);
      std::optional<nlohmann::json> stored_spec = stored.result ? ReadRunSpecJson(run_dir) : std::nullopt;
      if (stored.result && stored_spec && stored.result->value("run_id", "") == run.run_id &&
          RecordedRunIsReusable(run, StatusOfResultJson(*stored.result), *stored_spec, settings, stale)) {
        outcome.stale += stale ? 1 : 0;
        store.RecordRun(sweep_id, *stored_spec, *stored.result, std::filesystem::path("runs") / run.run_id);
        if (stale) MarkStale(settings.output_dir, run.run_id, store);
        ++outcome.already_done;
        continue;
      }
      outcome.stale += stale ? 1 : 0;
    }
    to_run.push_back(&run);
  }
  return to_run;
}

std::filesystem::path PrepareRunFolder(const std::filesystem::path& output_dir, const RunSpec& run) {
  const std::filesystem::path run_dir = RunFolder(output_dir, run.run_id);
  RemovePartialRun(run_dir);
  std::filesystem::create_directories(run_dir);
  // Not synced to disk: the supervisor hands out runs one after another, and a run.json lost to a crash of
  // the machine only makes its run start again (a run without result.json is never taken for done).
  WriteJsonAtomically(run_dir / "run.json", ToJson(run), Durability::kProcessCrash);
  return run_dir;
}

std::optional<FinishedRun> RecordWorkerEnding(const RunSpec& run, const WorkerEnding& ending,
                                              const std::filesystem::path& output_dir, ResultsStore& store,
                                              std::int64_t sweep_id) {
  const std::filesystem::path run_dir = RunFolder(output_dir, run.run_id);
  std::optional<PhaseTimer> phase(std::in_place, "record_read");
  StoredResult stored = ReadRunResult(run_dir);
  if (!stored.result && ending.interrupted) {
    // Interrupted before its result existed: nothing half-done may look like a result.
    RemovePartialRun(run_dir);
    return std::nullopt;
  }
  nlohmann::json result = stored.result ? std::move(*stored.result)
                                        : MissingResult(run, ending.reason + " (" + stored.problem + ")", false);
  if (!stored.result) WriteJsonAtomically(run_dir / "result.json", result);
  phase.emplace("record_store");
  store.RecordRun(sweep_id, ToJson(run), result, std::filesystem::path("runs") / run.run_id);
  phase.reset();
  FinishedRun finished;
  finished.run_id = run.run_id;
  finished.ok = StatusOfResultJson(result) == RunStatus::kOk;
  if (!finished.ok) {
    finished.reason = result.value("failure_kind", std::string(RunStatusName(RunStatus::kFailed))) + ": " +
                      result.value("reason", "");
  }
  if (result.contains("wall_s") && result["wall_s"].is_number()) finished.wall_s = result["wall_s"].get<double>();
  return finished;
}

std::size_t WriteSweepOutputs(const ResultsStore& store, const std::set<std::string>& matrix_ids,
                              const std::filesystem::path& output_dir) {
  std::vector<RunRecord> stored_runs;
  for (RunRecord& stored : store.Runs()) {
    if (matrix_ids.count(stored.run_id) > 0) stored_runs.push_back(std::move(stored));
  }
  std::size_t failed = 0;
  for (const RunRecord& stored : stored_runs) failed += stored.status == RunStatus::kOk ? 0 : 1;
  WriteResultFiles(stored_runs, output_dir);
  return failed;
}

SweepInfo SweepInfoFor(const SweepSettings& settings) {
  SweepInfo info;
  info.name = settings.name;
  info.config_path = settings.config_path;
  info.config_sha = settings.config_sha;
  info.slamsweep_version = SLAMSWEEP_VERSION;
  info.host = HostName();
  info.command_line = settings.command_line;
  return info;
}

}  // namespace slamsweep::orchestrator::inline sweep
