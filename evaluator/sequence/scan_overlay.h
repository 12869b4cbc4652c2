#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "evaluator/core/laser_scan.h"

namespace slamsweep::evaluator::inline sequence {

/// The scan's hits in its robot frame.
std::vector<Eigen::Vector3d> HitsOnRobot(const LaserScan& scan);

/// Nearest-hit look-ups in one scan, for laying another scan over it. Only the beams whose bearing
/// lies within the match radius of a point can hold its nearest hit, so a look-up reads a few beams.
class ScanNeighbours {
 public:
  /// `scan` must outlive this object.
  ScanNeighbours(const LaserScan& scan, double match_radius_m);

  std::size_t HitCount() const { return hit_count_; }

  /// Squared distance from `on_robot` (a point in this scan's robot frame) to the nearest hit, at
  /// most the match radius squared (a point with nothing near counts as that far).
  double SquaredDistance(const Eigen::Vector3d& on_robot) const;

 private:
  const LaserScan& scan_;
  double match_radius_m_;
  Eigen::Isometry3d robot_to_sensor_;
  std::vector<Eigen::Vector2d> points_;
  std::vector<bool> hit_;
  std::size_t hit_count_ = 0;
};

/// Summed capped squared distances from `hits` (another scan's hits in its robot frame), placed at
/// `placement` (that robot's pose in this scan's robot frame), to this scan's nearest hits.
double OverlayResidual(const ScanNeighbours& scan, const std::vector<Eigen::Vector3d>& hits,
                       const Eigen::Isometry3d& placement);

}  // namespace slamsweep::evaluator::inline sequence
