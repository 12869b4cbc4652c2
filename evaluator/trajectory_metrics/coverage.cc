#include "evaluator/trajectory_metrics/coverage.h"

#include <algorithm>
#include <cmath>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline trajectory_metrics {

nlohmann::json TrajectoryCoverage::ToJson() const {
  return {{"fraction", fraction},
          {"reference_start_s", reference_start_s},
          {"reference_end_s", reference_end_s},
          {"estimate_start_s", estimate_start_s},
          {"estimate_end_s", estimate_end_s}};
}

TrajectoryCoverage ComputeCoverage(const Trajectory& reference, const Trajectory& estimate) {
  if (reference.size() == 0) throw InputError("coverage: the reference trajectory is empty");
  const auto [ref_min, ref_max] = std::minmax_element(reference.stamps_s().begin(), reference.stamps_s().end());
  TrajectoryCoverage coverage;
  coverage.reference_start_s = *ref_min;
  coverage.reference_end_s = *ref_max;
  if (estimate.size() == 0) return coverage;
  const auto [est_min, est_max] = std::minmax_element(estimate.stamps_s().begin(), estimate.stamps_s().end());
  coverage.estimate_start_s = *est_min;
  coverage.estimate_end_s = *est_max;
  const double span = coverage.reference_end_s - coverage.reference_start_s;
  if (span <= 0.0) {
    coverage.fraction = coverage.reference_start_s >= *est_min && coverage.reference_start_s <= *est_max ? 1.0 : 0.0;
    return coverage;
  }
  const double overlap = std::min(*est_max, coverage.reference_end_s) - std::max(*est_min, coverage.reference_start_s);
  coverage.fraction = std::clamp(overlap / span, 0.0, 1.0);
  return coverage;
}

}  // namespace slamsweep::evaluator::inline trajectory_metrics
