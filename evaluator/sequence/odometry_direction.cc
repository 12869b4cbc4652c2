#include "evaluator/sequence/odometry_direction.h"

#include <cmath>
#include <cstdint>
#include <unordered_set>
#include <vector>

namespace slamsweep::evaluator {
namespace {

constexpr double kCellM = 0.04;
/// Steps shorter than this are not tested: the two hypotheses differ by less than two cells.
constexpr double kMinTestedStepM = 0.04;
/// A reading step that moves at least this far counts as moving.
constexpr double kMovingStepM = 0.02;
/// A stream needs this many moving steps, none backward, to be taken for one without signs.
constexpr std::size_t kMinMovingSteps = 100;
constexpr double kClearlyMoreFactor = 1.25;
constexpr std::size_t kClearlyMoreHits = 10;

std::int64_t CellKey(double x_m, double y_m) {
  const auto ix = static_cast<std::int64_t>(std::floor(x_m / kCellM));
  const auto iy = static_cast<std::int64_t>(std::floor(y_m / kCellM));
  return ix * 4'000'003 + iy;
}

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

std::size_t Agreeing(const std::unordered_set<std::int64_t>& cells, const std::vector<Eigen::Vector3d>& hits,
                     const Eigen::Isometry3d& placement) {
  std::size_t count = 0;
  for (const Eigen::Vector3d& hit : hits) {
    const Eigen::Vector3d placed = placement * hit;
    if (cells.contains(CellKey(placed.x(), placed.y()))) ++count;
  }
  return count;
}

bool ClearlyMore(std::size_t a, std::size_t b) {
  return static_cast<double>(a) >= kClearlyMoreFactor * static_cast<double>(b) && a >= b + kClearlyMoreHits;
}

Pose Negated(const Pose& step) {
  Pose reversed = step;
  reversed.position = -step.position;
  return reversed;
}

}  // namespace

StepDirection StepDirectionByScans(const LaserScan& earlier, const LaserScan& later, const Pose& step) {
  if (step.position.head<2>().norm() < kMinTestedStepM) return StepDirection::kUndecided;
  std::unordered_set<std::int64_t> cells;
  for (const Eigen::Vector3d& hit : HitsOnRobot(earlier)) cells.insert(CellKey(hit.x(), hit.y()));
  const std::vector<Eigen::Vector3d> hits = HitsOnRobot(later);
  const std::size_t along = Agreeing(cells, hits, step.ToIsometry());
  const std::size_t against = Agreeing(cells, hits, Negated(step).ToIsometry());
  if (ClearlyMore(against, along)) return StepDirection::kAgainst;
  if (ClearlyMore(along, against)) return StepDirection::kAlong;
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
