#include "evaluator/occupancy_mapping/scan_placement.h"

#include <cstdio>
#include <optional>
#include <string>

#include "evaluator/core/input_error.h"
#include "evaluator/trajectory_metrics/interpolation.h"

namespace slamsweep::evaluator::inline occupancy_mapping {

std::vector<PlacedScan> PlaceScans(std::span<const LaserScan> scans, std::span<const Pose> robot_poses) {
  if (scans.size() != robot_poses.size()) {
    throw InputError("mapping needs one robot pose per scan, got " + std::to_string(scans.size()) + " scans and " +
                     std::to_string(robot_poses.size()) + " poses");
  }
  std::vector<PlacedScan> placed;
  placed.reserve(scans.size());
  for (std::size_t i = 0; i < scans.size(); ++i) {
    if (!robot_poses[i].IsValid()) {
      throw InputError("robot pose " + std::to_string(i) + " (for scan " + std::to_string(i) +
                       "): expected finite position and unit quaternion");
    }
    placed.push_back(PlacedScan{&scans[i], robot_poses[i]});
  }
  return placed;
}

ScanPlacement PlaceScans(std::span<const LaserScan> scans, const Trajectory& trajectory) {
  const TrajectoryInterpolator interpolator(trajectory);
  ScanPlacement result;
  result.placed.reserve(scans.size());
  for (const LaserScan& scan : scans) {
    if (const std::optional<Pose> pose = interpolator.At(scan.stamp_s)) {
      result.placed.push_back(PlacedScan{&scan, *pose});
    } else {
      ++result.outside_trajectory;
    }
  }
  if (result.placed.empty() && !scans.empty()) {
    char range[96];
    std::snprintf(range, sizeof(range), "[%.6f, %.6f] s (%zu scans)", scans.front().stamp_s, scans.back().stamp_s,
                  scans.size());
    throw InputError(std::string("no scan stamp falls within the trajectory's time span: scans ") + range +
                     ", trajectory " + DescribeTimeRange(trajectory) +
                     "; are both on the same clock (try a time offset)?");
  }
  return result;
}

}  // namespace slamsweep::evaluator::inline occupancy_mapping
