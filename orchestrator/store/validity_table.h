#pragma once

#include <vector>

#include "evaluator/validity/metric_validity.h"
#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator {

/// A stored run as the metric validity study reads it: status, odometry flag, every flat metric
/// as "<metric>.<statistic>", and the resources (wall_s, cpu_s, peak_rss_kb) of runs that ran a
/// program (the odometry baseline runs none: its wall time is slamsweep's own rendering).
evaluator::ValidityRun ToValidityRun(const StoredRun& run);

/// The study of `runs` (evaluator::ComputeValidityStudy): the one computation behind summary.json's
/// "validity" and validity.csv.
evaluator::ValidityStudy ValidityStudyOf(const std::vector<StoredRun>& runs);

}  // namespace slamsweep::orchestrator
