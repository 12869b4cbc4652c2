#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "orchestrator/run/run_spec.h"
#include "orchestrator/service/service_metrics.h"
#include "orchestrator/service/sweep_entry.h"
#include "orchestrator/service/sweep_table.h"

namespace slamsweep::orchestrator::service {

/// The result.json of `run`'s folder in another sweep's result directory when it may stand for `run`:
/// the result is ok, and its run.json has the same run id (the same inputs, seed and algorithm), the
/// same build identity (slamsweep revision and program digests: the rerun-skip check's rule) and the
/// same evaluation options (which are not part of the run id but change the scores). nullopt otherwise.
std::optional<nlohmann::json> ReusableResult(const RunSpec& run, const std::filesystem::path& source_result_dir);

/// Makes `run`'s folder in `target_result_dir` a copy of its folder in `source_result_dir`: every file
/// hard-linked (copied when the file systems differ), then run.json written anew for `run` (its sweep
/// name and thresholds are the target sweep's). Results written later replace files, never edit them
/// in place, so the two sweeps' folders stay independent. A partial copy is removed on failure.
void LinkRunFolder(const RunSpec& run, const std::filesystem::path& source_result_dir,
                   const std::filesystem::path& target_result_dir);

/// Stands in for run `index` of the active sweep `entry` with an identical ok run of another sweep, the
/// newest first: its folder linked (LinkRunFolder), the run recorded in the sweep's results store, shown
/// reused in `sweeps` and counted in `metrics`. False when no other sweep's run can stand for it; a
/// source that fails on the way is logged and the next one tried.
bool ReuseIdenticalRun(SweepTable& sweeps, SweepEntry& entry, std::size_t index, ServiceMetrics& metrics);

}  // namespace slamsweep::orchestrator::service
