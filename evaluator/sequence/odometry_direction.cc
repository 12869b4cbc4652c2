#include "evaluator/sequence/odometry_direction.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

namespace slamsweep::evaluator {
namespace {

/// A later hit farther than this from every earlier hit counts as this far (something newly seen).
constexpr double kMatchRadiusM = 0.10;
/// Steps shorter than this are not tested: the two placements lie less than the logs' 1 cm range
/// resolution apart.
constexpr double kMinTestedStepM = 0.005;
/// One placement must leave at most this share of the other's summed squared distances.
constexpr double kClearlyBetterRatio = 0.9;
/// Scans with fewer hits than this decide nothing.
constexpr std::size_t kMinHits = 20;
/// A reading step that moves at least this far counts as moving.
constexpr double kMovingStepM = 0.02;
/// A stream needs this many moving steps, none backward, to be taken for one without signs.
constexpr std::size_t kMinMovingSteps = 100;

/// The scan's hits in its robot frame.
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

/// The earlier scan's hits by beam, in its sensor frame, for nearest-hit look-ups near a bearing.
class BeamNeighbours {
 public:
  explicit BeamNeighbours(const LaserScan& scan)
      : scan_(scan), robot_to_sensor_(scan.sensor_pose_on_robot.ToIsometry().inverse()) {
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

  std::size_t HitCount() const { return hit_count_; }

  /// Squared distance from `on_robot` (the earlier robot frame) to the nearest earlier hit, at most
  /// kMatchRadiusM squared. Only beams whose bearing lies within that radius of the point can hold it.
  double SquaredDistance(const Eigen::Vector3d& on_robot) const {
    const Eigen::Vector3d in_sensor = robot_to_sensor_ * on_robot;
    const Eigen::Vector2d point = in_sensor.head<2>();
    const double increment = std::abs(scan_.angle_increment_rad);
    const auto count = static_cast<std::ptrdiff_t>(points_.size());
    double best = kMatchRadiusM * kMatchRadiusM;
    if (count == 0 || increment == 0.0) return best;
    const double bearing = std::atan2(point.y(), point.x());
    const double offset = std::remainder(bearing - scan_.angle_min_rad, 2.0 * std::numbers::pi);
    const auto centre = static_cast<std::ptrdiff_t>(std::lround(offset / scan_.angle_increment_rad));
    const double spread = std::atan2(kMatchRadiusM, std::max(point.norm() - kMatchRadiusM, 0.0));
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

 private:
  const LaserScan& scan_;
  Eigen::Isometry3d robot_to_sensor_;
  std::vector<Eigen::Vector2d> points_;
  std::vector<bool> hit_;
  std::size_t hit_count_ = 0;
};

/// Summed (capped) squared distances from the later hits, placed at `placement`, to the earlier hits.
double Residual(const BeamNeighbours& earlier, const std::vector<Eigen::Vector3d>& later_hits,
                const Eigen::Isometry3d& placement) {
  double sum = 0.0;
  for (const Eigen::Vector3d& hit : later_hits) sum += earlier.SquaredDistance(placement * hit);
  return sum;
}

Pose Negated(const Pose& step) {
  Pose reversed = step;
  reversed.position = -step.position;
  return reversed;
}

}  // namespace

StepDirection StepDirectionByScans(const LaserScan& earlier, const LaserScan& later, const Pose& step) {
  if (step.position.head<2>().norm() < kMinTestedStepM) return StepDirection::kUndecided;
  const std::vector<Eigen::Vector3d> hits = HitsOnRobot(later);
  const BeamNeighbours neighbours(earlier);
  if (hits.size() < kMinHits || neighbours.HitCount() < kMinHits) return StepDirection::kUndecided;
  const double along = Residual(neighbours, hits, step.ToIsometry());
  const double against = Residual(neighbours, hits, Negated(step).ToIsometry());
  if (against < kClearlyBetterRatio * along) return StepDirection::kAgainst;
  if (along < kClearlyBetterRatio * against) return StepDirection::kAlong;
  return StepDirection::kUndecided;
}

ReversingRepair RestoreReversing(Trajectory& readings, std::span<const std::size_t> scan_readings,
                                 std::span<const LaserScan> scans) {
  ReversingRepair repair;
  const std::vector<Pose>& poses = readings.poses();
  std::vector<Pose> steps(poses.size());
  for (std::size_t j = 1; j < poses.size(); ++j) {
    steps[j] = Relative(poses[j - 1], poses[j]);
    if (steps[j].position.head<2>().norm() < kMovingStepM) continue;
    ++repair.moving_steps;
    if (steps[j].position.x() < 0.0) ++repair.logged_backward_steps;
  }
  repair.unsigned_stream = repair.moving_steps >= kMinMovingSteps && repair.logged_backward_steps == 0;
  if (!repair.unsigned_stream) return repair;

  std::vector<bool> reversed(poses.size(), false);
  for (std::size_t i = 1; i < scans.size() && i < scan_readings.size(); ++i) {
    const std::size_t from = scan_readings[i - 1];
    const std::size_t to = scan_readings[i];
    const Pose step = Relative(poses[from], poses[to]);
    if (step.position.head<2>().norm() < kMinTestedStepM) continue;
    ++repair.scan_steps_tested;
    if (StepDirectionByScans(scans[i - 1], scans[i], step) != StepDirection::kAgainst) continue;
    ++repair.scan_steps_reversed;
    for (std::size_t j = from + 1; j <= to; ++j) reversed[j] = true;
  }
  if (repair.scan_steps_reversed == 0) return repair;
  std::vector<Pose>& chain = readings.mutable_poses();
  for (std::size_t j = 1; j < chain.size(); ++j) chain[j] = chain[j - 1] * (reversed[j] ? Negated(steps[j]) : steps[j]);
  return repair;
}

}  // namespace slamsweep::evaluator
