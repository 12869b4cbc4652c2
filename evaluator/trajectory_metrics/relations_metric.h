#pragma once

#include <cstddef>
#include <string>
#include <nlohmann/json.hpp>

#include "evaluator/core/relation.h"
#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline trajectory_metrics {

struct RelationsOptions {
  /// Added to both stamps of every relation before the estimate is looked up, seconds.
  double t_offset_s = 0.0;
};

/// Summary of the Kuemmerle et al. (2009) relation errors. std is the population standard
/// deviation (divide by n), as everywhere in slamsweep.
struct RelationsResult {
  double translation_abs_mean_m = 0.0;
  double translation_abs_std_m = 0.0;
  double translation_sq_mean_m2 = 0.0;
  double translation_sq_std_m2 = 0.0;
  double rotation_abs_mean_deg = 0.0;
  double rotation_abs_std_deg = 0.0;
  double rotation_sq_mean_deg2 = 0.0;
  double rotation_sq_std_deg2 = 0.0;
  /// Relations scored, and relations not covered: t1 or t2 (after the offset) lies outside the
  /// estimate's time span. Relations outside the log itself are never given to the metric
  /// (Sequence::relations_outside_log counts them).
  std::size_t used = 0;
  std::size_t not_covered = 0;
  /// "odometry" (the estimate moved by the odometry between its poses, OdometryInterpolator) or
  /// "linear" (no odometry given); relation stamps the odometry did not cover were interpolated
  /// linearly all the same, and are counted.
  std::string interpolation = "linear";
  std::size_t linear_fallbacks = 0;
  /// {"t_offset_s", "interpolation"}.
  nlohmann::json specification;

  /// Every field above under its own name, plus "metric": "relations".
  nlohmann::json ToJson() const;
};

/// The relations metric of Kuemmerle et al.: for each relation (t1, t2, expected), the estimate's
/// poses P1, P2 at t1 and t2; the error is E = (P1^-1 P2) * expected^-1, scored as |t(E)| (m) and
/// the angle of R(E) (deg). Between the estimate's poses, P is its last pose before t moved by the
/// odometry the program was given (OdometryInterpolator), or without odometry interpolated linearly
/// (linear translation, shortest-arc slerp rotation).
class RelationsMetric {
 public:
  /// Throws InputError when t_offset_s is not finite.
  explicit RelationsMetric(RelationsOptions options);

  /// Throws InputError when the estimate's stamps decrease, or when no relation can be used
  /// (the message names the estimate's and the relations' time ranges).
  /// `odometry`: the program's odometry (its readings, when denser than its scans), or null.
  RelationsResult Compute(const Trajectory& estimate, const Relations& relations,
                          const Trajectory* odometry = nullptr) const;

 private:
  RelationsOptions options_;
};

}  // namespace slamsweep::evaluator::inline trajectory_metrics
