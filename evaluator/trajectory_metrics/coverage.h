#pragma once

#include <nlohmann/json.hpp>

#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline trajectory_metrics {

/// How much of the reference's time span an estimate covers. Measured by time span, not by the
/// number of poses that associate: a run that reports every scan (2,725) against a reference of
/// keyframes (910) covers it fully, and one that stops half-way covers half whatever its density.
struct TrajectoryCoverage {
  double reference_start_s = 0.0;
  double reference_end_s = 0.0;
  double estimate_start_s = 0.0;
  double estimate_end_s = 0.0;
  /// The part of [reference_start, reference_end] inside [estimate_start, estimate_end], as a
  /// fraction of the reference's span, in [0, 1]. An empty estimate covers 0; a reference of one
  /// stamp is covered (1) when that stamp lies in the estimate's span, else 0.
  double fraction = 0.0;

  /// {"fraction", "reference_start_s", "reference_end_s", "estimate_start_s", "estimate_end_s"}
  nlohmann::json ToJson() const;
};

/// Throws InputError when the reference is empty. Stamps are taken as recorded (each trajectory's
/// first and last stamp); both must be on one clock, as the trajectory metrics assume.
TrajectoryCoverage ComputeCoverage(const Trajectory& reference, const Trajectory& estimate);

}  // namespace slamsweep::evaluator::inline trajectory_metrics
