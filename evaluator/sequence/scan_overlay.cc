#include "evaluator/sequence/scan_overlay.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace slamsweep::evaluator::inline sequence {

std::vector<Eigen::Vector3d> HitsOnRobot(const LaserScan& scan) {
  const Eigen::Isometry3d mount = scan.sensor_pose_on_robot.ToIsometry();
  std::vector<Eigen::Vector3d> hits;
  hits.reserve(scan.BeamCount());
  for (std::size_t b = 0; b < scan.BeamCount(); ++b) {
    const float range = scan.ranges_m[b];
    if (!scan.IsHit(range)) continue;
    const double angle = scan.BeamAngleRad(b);
    hits.push_back(mount * Eigen::Vector3d(range * std::cos(angle), range * std::sin(angle), 0.0));
  }
  return hits;
}

ScanNeighbours::ScanNeighbours(const LaserScan& scan, double match_radius_m)
    : scan_(scan), match_radius_m_(match_radius_m), robot_to_sensor_(scan.sensor_pose_on_robot.ToIsometry().inverse()) {
  points_.reserve(scan.BeamCount());
  hit_.reserve(scan.BeamCount());
  for (std::size_t b = 0; b < scan.BeamCount(); ++b) {
    const float range = scan.ranges_m[b];
    const double angle = scan.BeamAngleRad(b);
    points_.emplace_back(range * std::cos(angle), range * std::sin(angle));
    hit_.push_back(scan.IsHit(range));
    hit_count_ += hit_.back() ? 1 : 0;
  }
}

double ScanNeighbours::SquaredDistance(const Eigen::Vector3d& on_robot) const {
  const Eigen::Vector3d in_sensor = robot_to_sensor_ * on_robot;
  const Eigen::Vector2d point = in_sensor.head<2>();
  const double increment = std::abs(scan_.angle_increment_rad);
  const auto count = static_cast<std::ptrdiff_t>(points_.size());
  double best = match_radius_m_ * match_radius_m_;
  if (count == 0 || increment == 0.0) return best;
  const double bearing = std::atan2(point.y(), point.x());
  const double offset = std::remainder(bearing - scan_.angle_min_rad, 2.0 * std::numbers::pi);
  const auto centre = static_cast<std::ptrdiff_t>(std::lround(offset / scan_.angle_increment_rad));
  const double spread = std::atan2(match_radius_m_, std::max(point.norm() - match_radius_m_, 0.0));
  const double beams_apart = std::min(std::ceil(spread / increment) + 1.0, static_cast<double>(count));
  const auto half_window = static_cast<std::ptrdiff_t>(beams_apart);
  const std::ptrdiff_t first = std::max<std::ptrdiff_t>(centre - half_window, 0);
  const std::ptrdiff_t last = std::min<std::ptrdiff_t>(centre + half_window, count - 1);
  for (std::ptrdiff_t b = first; b <= last; ++b) {
    const auto index = static_cast<std::size_t>(b);
    if (hit_[index]) best = std::min(best, (points_[index] - point).squaredNorm());
  }
  return best;
}

double OverlayResidual(const ScanNeighbours& scan, const std::vector<Eigen::Vector3d>& hits,
                       const Eigen::Isometry3d& placement) {
  double sum = 0.0;
  for (const Eigen::Vector3d& hit : hits) sum += scan.SquaredDistance(placement * hit);
  return sum;
}

}  // namespace slamsweep::evaluator::inline sequence
