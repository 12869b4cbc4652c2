#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "evaluator/sequence/scan_spacing.h"
#include "orchestrator/run/run_record.h"

namespace slamsweep::report::inline model {

/// How far apart a table's scans are: result.json's sequence.scan_spacing of the first of `table_runs` (indices into
/// `runs`, in table order) that recorded a readable block; every run of a table reads the same sequence.
/// Absent when none did (runs recorded before the block, or inputs never prepared).
std::optional<evaluator::ScanSpacing> TableScanSpacing(const std::vector<orchestrator::RunRecord>& runs,
                                                       const std::vector<std::size_t>& table_runs);

}  // namespace slamsweep::report::inline model
