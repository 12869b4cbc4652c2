#pragma once

#include <vector>

#include "evaluator/validity/metric_validity.h"
#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator::inline store {

/// A run as the metric validity study reads it: status, odometry flag, every flat metric with a value
/// as "<metric>.<statistic>", and the resources (wall_s, cpu_s, peak_rss_kb) of runs that ran a
/// program (the odometry baseline runs none: its wall time is slamsweep's own rendering). The store's
/// outputs and the report's validity page convert their runs alike, so both hold the same numbers.
evaluator::ValidityRun ToValidityRun(const RunRecord& run);
std::vector<evaluator::ValidityRun> ToValidityRuns(const std::vector<RunRecord>& runs);

/// The study of `runs` (evaluator::ComputeValidityStudy): the one computation behind summary.json's
/// "validity" and validity.csv.
evaluator::ValidityStudy ValidityStudyOf(const std::vector<RunRecord>& runs);

}  // namespace slamsweep::orchestrator::inline store
