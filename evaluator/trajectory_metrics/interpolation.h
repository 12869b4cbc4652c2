#pragma once

#include <optional>

#include "evaluator/core/pose.h"
#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline trajectory_metrics {

/// The pose a `fraction` (0 = a, 1 = b) of the way from a to b: positions linearly, orientations
/// by slerp along the shorter arc (q and -q are the same rotation, so the sign is chosen to keep
/// the turn below 180 degrees).
Pose InterpolatePose(const Pose& a, const Pose& b, double fraction);

/// Poses of a trajectory at arbitrary times. Holds a reference: the trajectory must outlive it.
class TrajectoryInterpolator {
 public:
  /// Throws InputError when the trajectory is empty or its stamps decrease (naming the pose).
  explicit TrajectoryInterpolator(const Trajectory& trajectory);

  /// The pose at stamp_s, interpolated between the neighbouring poses; a recorded pose when
  /// stamp_s equals its stamp; nullopt outside [first stamp, last stamp] (no extrapolation).
  std::optional<Pose> At(double stamp_s) const;

 private:
  const Trajectory& trajectory_;
};

/// Poses of an estimate at arbitrary times, moved by the robot's odometry between them: at time t,
/// the estimate's last pose at or before t composed with the odometry's motion from that pose's
/// stamp to t (the odometry itself interpolated between its readings). This is how a SLAM program
/// that estimates keyframes places the robot between them (GMapping's own log does it), and it keeps
/// a robot that turns on the spot between two keyframes turning. Holds references to both.
class OdometryInterpolator {
 public:
  /// Throws InputError when either trajectory is empty or its stamps decrease.
  OdometryInterpolator(const Trajectory& estimate, const Trajectory& odometry);

  /// nullopt outside [first, last] stamp of the estimate; the estimate's pose at one of its stamps.
  /// Where the odometry does not cover both times, the estimate is interpolated linearly instead and
  /// `linear_fallback` (when given) is set.
  std::optional<Pose> At(double stamp_s, bool* linear_fallback = nullptr) const;

 private:
  const Trajectory& estimate_;
  TrajectoryInterpolator linear_;
  TrajectoryInterpolator odometry_;
};

}  // namespace slamsweep::evaluator::inline trajectory_metrics
