#include "evaluator/trajectory_metrics/interpolation.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline trajectory_metrics {

Pose InterpolatePose(const Pose& a, const Pose& b, double fraction) {
  Pose pose;
  pose.position = a.position + fraction * (b.position - a.position);
  // Eigen's slerp flips the sign of b when a.dot(b) < 0, i.e. takes the shorter arc.
  pose.orientation = a.orientation.slerp(fraction, b.orientation).normalized();
  return pose;
}

TrajectoryInterpolator::TrajectoryInterpolator(const Trajectory& trajectory) : trajectory_(trajectory) {
  if (trajectory.empty()) throw InputError("interpolation: the trajectory has no poses");
  const std::vector<double>& stamps = trajectory.stamps_s();
  const auto decreasing = std::adjacent_find(stamps.begin(), stamps.end(), std::greater<double>());
  if (decreasing != stamps.end()) {
    const std::size_t index = static_cast<std::size_t>(decreasing - stamps.begin()) + 1;
    char buffer[160];
    std::snprintf(buffer, sizeof(buffer), "stamp %.9g s comes after %.9g s", stamps[index], stamps[index - 1]);
    throw InputError("interpolation: pose " + std::to_string(index) + ": expected non-decreasing timestamps, but " +
                     buffer);
  }
}

std::optional<Pose> TrajectoryInterpolator::At(double stamp_s) const {
  const std::vector<double>& stamps = trajectory_.stamps_s();
  const std::vector<Pose>& poses = trajectory_.poses();
  const auto after = std::upper_bound(stamps.begin(), stamps.end(), stamp_s);
  if (after == stamps.begin()) return std::nullopt;
  const std::size_t below = static_cast<std::size_t>(after - stamps.begin()) - 1;
  if (stamps[below] == stamp_s) return poses[below];
  if (after == stamps.end()) return std::nullopt;
  const std::size_t above = below + 1;
  // stamps[below] < stamp_s < stamps[above], so the division is safe.
  const double fraction = (stamp_s - stamps[below]) / (stamps[above] - stamps[below]);
  return InterpolatePose(poses[below], poses[above], fraction);
}

OdometryInterpolator::OdometryInterpolator(const Trajectory& estimate, const Trajectory& odometry)
    : estimate_(estimate), linear_(estimate), odometry_(odometry) {}

std::optional<Pose> OdometryInterpolator::At(double stamp_s, bool* linear_fallback) const {
  if (linear_fallback != nullptr) *linear_fallback = false;
  const std::vector<double>& stamps = estimate_.stamps_s();
  const auto after = std::upper_bound(stamps.begin(), stamps.end(), stamp_s);
  if (after == stamps.begin()) return std::nullopt;
  const std::size_t below = static_cast<std::size_t>(after - stamps.begin()) - 1;
  if (stamps[below] == stamp_s) return estimate_.poses()[below];
  if (after == stamps.end()) return std::nullopt;
  const std::optional<Pose> odometry_from = odometry_.At(stamps[below]);
  const std::optional<Pose> odometry_to = odometry_.At(stamp_s);
  if (!odometry_from || !odometry_to) {
    if (linear_fallback != nullptr) *linear_fallback = true;
    return linear_.At(stamp_s);
  }
  return estimate_.poses()[below] * Relative(*odometry_from, *odometry_to);
}

}  // namespace slamsweep::evaluator::inline trajectory_metrics
