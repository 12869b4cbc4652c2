#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "orchestrator/run/run_spec.h"
#include "orchestrator/store/results_store.h"
#include "orchestrator/supervisor/executor.h"
#include "orchestrator/sweep/status.h"
#include "orchestrator/sweep/sweep_runner.h"

namespace slamsweep::orchestrator::inline sweep {

// The steps of one sweep into one output directory, shared by `slamsweep run` (RunSweep) and the
// service's scheduler (orchestrator/service), so that both leave exactly the same files and records.

/// What the output directory still lacks: the runs of `runs` that its store does not hold under the
/// same build identity (RecordedRunIsReusable), after adopting result.json files the store missed
/// (the orchestrator died between a worker's rename and the store's commit). Counts already_done and
/// stale into `outcome`.
std::vector<const RunSpec*> RunsStillToDo(const std::vector<RunSpec>& runs, const SweepSettings& settings,
                                          ResultsStore& store, std::int64_t sweep_id, SweepOutcome& outcome);

/// The run's folder made ready for a fresh attempt: what an earlier attempt left is removed and
/// run.json is written. Returns the folder.
std::filesystem::path PrepareRunFolder(const std::filesystem::path& output_dir, const RunSpec& run);

/// Records a worker's ending in the run's folder and the store: its result.json, or a failed result
/// naming the worker's fate when it left none. A run interrupted before it had a result leaves
/// nothing (its folder is removed) and gives nullopt: it counts as not started.
std::optional<FinishedRun> RecordWorkerEnding(const RunSpec& run, const WorkerEnding& ending,
                                              const std::filesystem::path& output_dir, ResultsStore& store,
                                              std::int64_t sweep_id);

/// summary.json, summary.csv, runs.csv and junit.xml of the runs in `matrix_ids`, from the store.
/// Returns how many of them are recorded as failed.
std::size_t WriteSweepOutputs(const ResultsStore& store, const std::set<std::string>& matrix_ids,
                              const std::filesystem::path& output_dir);

/// The store's record of a sweep as it starts (name, config, host, version, command line).
SweepInfo SweepInfoFor(const SweepSettings& settings);

}  // namespace slamsweep::orchestrator::inline sweep
