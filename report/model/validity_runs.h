#pragma once

#include <vector>

#include "evaluator/validity/metric_validity.h"
#include "report/model/run_record.h"

namespace slamsweep::report {

/// A run as the metric validity study reads it: status, odometry flag, every flat metric as
/// "<metric>.<statistic>", and the resources of runs that ran a program (the odometry baseline runs
/// none: its wall time is slamsweep's own rendering). The store converts its runs alike
/// (orchestrator/store/validity_table.h), so the page and summary.json hold the same numbers.
evaluator::ValidityRun ToValidityRun(const RunRecord& run);
std::vector<evaluator::ValidityRun> ToValidityRuns(const std::vector<RunRecord>& runs);

}  // namespace slamsweep::report
