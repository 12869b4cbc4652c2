#pragma once

#include <optional>

#include "evaluator/core/pose.h"
#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator {

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

}  // namespace slamsweep::evaluator
