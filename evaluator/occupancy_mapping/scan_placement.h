#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/pose.h"
#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline occupancy_mapping {

/// A scan and the robot pose it was taken from. Does not own the scan: the scans must outlive
/// every PlacedScan that points at them.
struct PlacedScan {
  const LaserScan* scan = nullptr;
  Pose robot_pose;
};

/// Scans placed by interpolating a trajectory at their stamps.
struct ScanPlacement {
  std::vector<PlacedScan> placed;
  /// Scans whose stamp lies outside the trajectory's time span (SLAM outputs often start late).
  std::size_t outside_trajectory = 0;
};

/// Pairs scan i with robot_poses[i]. Throws InputError when the counts differ or a pose is not
/// finite (naming its index).
std::vector<PlacedScan> PlaceScans(std::span<const LaserScan> scans, std::span<const Pose> robot_poses);

/// Places each scan at the trajectory's pose at its stamp (TrajectoryInterpolator: linear in
/// position, shortest-arc slerp in rotation); scans outside the span are left out and counted.
/// Throws InputError when the trajectory is empty or its stamps decrease, or when no scan falls
/// in its span (naming both time ranges).
ScanPlacement PlaceScans(std::span<const LaserScan> scans, const Trajectory& trajectory);

}  // namespace slamsweep::evaluator::inline occupancy_mapping
