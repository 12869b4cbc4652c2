#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "orchestrator/run/run_record.h"

namespace slamsweep::report::inline model {

using orchestrator::FlatMetric;
using orchestrator::RunOutputs;
using orchestrator::RunRecord;
using orchestrator::RunStatus;
using orchestrator::RunStatusName;

/// Reads runs/<id>/run.json and result.json. Never throws for a bad run: a missing result.json
/// gives kUnfinished, a malformed file gives kUnreadable with `reason` naming the file and field,
/// because one broken run must not hide the others from the report.
RunRecord LoadRun(const std::filesystem::path& run_dir);

/// Every run folder under `result_dir`/runs, sorted by run id (so the report is reproducible).
/// Throws evaluator::InputError when `result_dir` or its runs/ folder does not exist.
std::vector<RunRecord> LoadRuns(const std::filesystem::path& result_dir);

}  // namespace slamsweep::report::inline model
