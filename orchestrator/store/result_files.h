#pragma once

#include <filesystem>
#include <vector>

#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator::inline store {

/// Writes a result directory's tables from its runs: summary.json, summary.csv, runs.csv,
/// validity.csv (with reference data) and junit.xml. The metric validity study, whose bootstrap
/// is the costly part, is computed once for summary.json and validity.csv.
void WriteResultFiles(const std::vector<RunRecord>& runs, const std::filesystem::path& output_dir);

}  // namespace slamsweep::orchestrator::inline store
