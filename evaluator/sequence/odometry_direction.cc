#include "evaluator/sequence/odometry_direction.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "evaluator/sequence/scan_overlay.h"

namespace slamsweep::evaluator::inline sequence {
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

Pose Negated(const Pose& step) {
  Pose reversed = step;
  reversed.position = -step.position;
  return reversed;
}

}  // namespace

StepDirection StepDirectionByScans(const LaserScan& earlier, const LaserScan& later, const Pose& step) {
  if (step.position.head<2>().norm() < kMinTestedStepM) return StepDirection::kUndecided;
  const std::vector<Eigen::Vector3d> hits = HitsOnRobot(later);
  const ScanNeighbours neighbours(earlier, kMatchRadiusM);
  if (hits.size() < kMinHits || neighbours.HitCount() < kMinHits) return StepDirection::kUndecided;
  const double along = OverlayResidual(neighbours, hits, step.ToIsometry());
  const double against = OverlayResidual(neighbours, hits, Negated(step).ToIsometry());
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

}  // namespace slamsweep::evaluator::inline sequence
