#include "evaluator/trajectory_metrics/relations_metric.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/core/statistics.h"
#include "evaluator/trajectory_metrics/interpolation.h"

namespace slamsweep::evaluator::inline trajectory_metrics {
namespace {

std::string DescribeRelationsRange(const Relations& relations, double offset_s) {
  if (relations.empty()) return "no relations";
  double first = relations.front().t1_s;
  double last = first;
  for (const Relation& relation : relations) {
    first = std::min({first, relation.t1_s, relation.t2_s});
    last = std::max({last, relation.t1_s, relation.t2_s});
  }
  char buffer[160];
  std::snprintf(buffer, sizeof(buffer), "[%.6f, %.6f] s (%zu relations, t_offset %.9g s applied)", first + offset_s,
                last + offset_s, relations.size(), offset_s);
  return buffer;
}

struct MeanStd {
  double mean = 0.0;
  double std = 0.0;
};

MeanStd Summarise(const std::vector<double>& values) {
  const ErrorStatistics statistics = ComputeStatistics(values);
  return MeanStd{statistics.mean, statistics.std};
}

std::vector<double> Squared(const std::vector<double>& values) {
  std::vector<double> squared(values.size());
  std::transform(values.begin(), values.end(), squared.begin(), [](double v) { return v * v; });
  return squared;
}

}  // namespace

nlohmann::json RelationsResult::ToJson() const {
  return nlohmann::json{{"metric", "relations"},
                        {"translation_abs_mean_m", translation_abs_mean_m},
                        {"translation_abs_std_m", translation_abs_std_m},
                        {"translation_sq_mean_m2", translation_sq_mean_m2},
                        {"translation_sq_std_m2", translation_sq_std_m2},
                        {"rotation_abs_mean_deg", rotation_abs_mean_deg},
                        {"rotation_abs_std_deg", rotation_abs_std_deg},
                        {"rotation_sq_mean_deg2", rotation_sq_mean_deg2},
                        {"rotation_sq_std_deg2", rotation_sq_std_deg2},
                        {"used", used},
                        {"not_covered", not_covered},
                        {"interpolation", interpolation},
                        {"linear_fallbacks", linear_fallbacks},
                        {"specification", specification}};
}

RelationsMetric::RelationsMetric(RelationsOptions options) : options_(options) {
  if (!std::isfinite(options_.t_offset_s)) {
    throw InputError("option t_offset_s (--t-offset): expected a finite number of seconds");
  }
}

RelationsResult RelationsMetric::Compute(const Trajectory& estimate, const Relations& relations,
                                         const Trajectory* odometry) const {
  if (estimate.empty()) {
    throw InputError("relations metric: the estimate has no poses; relations cover " +
                     DescribeRelationsRange(relations, options_.t_offset_s));
  }
  const TrajectoryInterpolator linear(estimate);
  std::optional<OdometryInterpolator> by_odometry;
  if (odometry != nullptr && !odometry->empty()) by_odometry.emplace(estimate, *odometry);
  std::size_t linear_fallbacks = 0;
  const auto pose_at = [&](double stamp_s) -> std::optional<Pose> {
    if (!by_odometry) return linear.At(stamp_s);
    bool fallback = false;
    std::optional<Pose> pose = by_odometry->At(stamp_s, &fallback);
    if (fallback) ++linear_fallbacks;
    return pose;
  };
  std::vector<double> translation_m;
  std::vector<double> rotation_deg;
  translation_m.reserve(relations.size());
  rotation_deg.reserve(relations.size());
  for (const Relation& relation : relations) {
    const std::optional<Pose> first = pose_at(relation.t1_s + options_.t_offset_s);
    const std::optional<Pose> second = pose_at(relation.t2_s + options_.t_offset_s);
    if (!first || !second) continue;
    const Pose error = Relative(*first, *second) * relation.delta.Inverse();
    translation_m.push_back(error.position.norm());
    rotation_deg.push_back(RadToDeg(RotationAngleRad(error.orientation)));
  }

  RelationsResult result;
  result.used = translation_m.size();
  result.not_covered = relations.size() - result.used;
  result.interpolation = by_odometry ? "odometry" : "linear";
  result.linear_fallbacks = linear_fallbacks;
  result.specification = nlohmann::json{{"t_offset_s", options_.t_offset_s}, {"interpolation", result.interpolation}};
  if (result.used == 0) {
    throw InputError("relations metric: none of the relations lies inside the estimate's time span; estimate " +
                     DescribeTimeRange(estimate) + ", relations " +
                     DescribeRelationsRange(relations, options_.t_offset_s) +
                     "; check that both use the same clock or set --t-offset");
  }
  const MeanStd translation = Summarise(translation_m);
  const MeanStd translation_sq = Summarise(Squared(translation_m));
  const MeanStd rotation = Summarise(rotation_deg);
  const MeanStd rotation_sq = Summarise(Squared(rotation_deg));
  result.translation_abs_mean_m = translation.mean;
  result.translation_abs_std_m = translation.std;
  result.translation_sq_mean_m2 = translation_sq.mean;
  result.translation_sq_std_m2 = translation_sq.std;
  result.rotation_abs_mean_deg = rotation.mean;
  result.rotation_abs_std_deg = rotation.std;
  result.rotation_sq_mean_deg2 = rotation_sq.mean;
  result.rotation_sq_std_deg2 = rotation_sq.std;
  return result;
}

}  // namespace slamsweep::evaluator::inline trajectory_metrics
