#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline adapters {

/// One "warning: ..." line per sequence of `runs` whose consecutive scans are too far apart for scan
/// matching (evaluator SparseScanWarning), each sequence loaded once as its runs' input starts
/// (LoadRunSequence: with its max_scans cut; through the sweep's prepared inputs in `cache_dir` when it is not
/// empty, so that the runs find the sequence prepared); "" when there is none. A sequence that cannot be
/// loaded is left out: its runs fail with the reason.
std::string SparseSequenceWarnings(const std::vector<RunSpec>& runs, const std::filesystem::path& cache_dir = {});

}  // namespace slamsweep::orchestrator::inline adapters
