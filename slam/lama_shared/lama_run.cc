#include "slam/lama_shared/lama_run.h"

#include <algorithm>
#include <cmath>

#include "evaluator/core/input_error.h"
#include "slam/common/key_pose_trajectory.h"

namespace slamsweep::slam::lama_driver {

using evaluator::InputError;

lama::PointCloudXYZ::Ptr LamaCloud(const evaluator::LaserScan& scan, const ScanOptions& options) {
  const double max_range =
      options.mrange == 0.0 || options.mrange > scan.range_max_m ? scan.range_max_m : options.mrange;
  auto cloud = std::make_shared<lama::PointCloudXYZ>();
  const evaluator::Pose& mount = scan.sensor_pose_on_robot;
  cloud->sensor_origin_ = Eigen::Vector3d(mount.position.x(), mount.position.y(), 0.0);
  cloud->sensor_orientation_ = Eigen::Quaterniond(Eigen::AngleAxisd(mount.Yaw(), Eigen::Vector3d::UnitZ()));
  cloud->points.reserve(scan.BeamCount());
  for (std::size_t i = 0; i < scan.BeamCount(); i += static_cast<std::size_t>(options.beam_step)) {
    // The nodes compare in single precision, as a ROS LaserScan holds its ranges and limits.
    const float range = scan.ranges_m[i];
    if (!std::isfinite(range)) continue;
    if (range >= static_cast<float>(max_range) || range <= static_cast<float>(scan.range_min_m)) continue;
    const double angle = scan.BeamAngleRad(i);
    cloud->points.emplace_back(range * std::cos(angle), range * std::sin(angle), 0.0);
  }
  return cloud;
}

evaluator::OccupancyGrid LamaMap(const lama::FrequencyOccupancyMap& map) {
  lama::Vector3ui low, high;
  map.bounds(low, high);  // without a patch, low stays above high
  if (low.x() >= high.x() || low.y() >= high.y()) return evaluator::OccupancyGrid(1, 1, map.resolution);
  const int width = static_cast<int>(high.x() - low.x());
  const int height = static_cast<int>(high.y() - low.y());
  // m2w gives a cell's centre: the grid's origin is the lower-left corner of its first cell.
  const Eigen::Vector3d first = map.m2w(low);
  const double half = 0.5 * map.resolution;
  evaluator::OccupancyGrid grid(width, height, map.resolution, {first.x() - half, first.y() - half, 0.0});
  map.visit_all_cells([&](const lama::Vector3ui& cell) {
    const int x = static_cast<int>(cell.x() - low.x());
    const int y = static_cast<int>(cell.y() - low.y());
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    if (map.isFree(cell)) {
      grid.at(height - 1 - y, x) = 0.0f;
    } else if (map.isOccupied(cell)) {
      grid.at(height - 1 - y, x) = 1.0f;
    }
  });
  return grid;
}

void WriteLamaResult(const evaluator::RobotLog& robot, const std::map<double, evaluator::Pose>& key_poses,
                     const lama::FrequencyOccupancyMap& map, DriverOutputs& outputs) {
  outputs.ReplaceTrajectory(TrajectoryFromKeyPoses(robot, key_poses));
  const evaluator::OccupancyGrid grid = LamaMap(map);
  outputs.WriteStage(robot.scans.size() - 1, grid);
  outputs.WriteFinal(grid);
}

lama::Pose2D LamaPose(const evaluator::Pose& pose) {
  return lama::Pose2D(pose.position.x(), pose.position.y(), pose.Yaw());
}

evaluator::Pose ToPose(const lama::Pose2D& pose) {
  return evaluator::Pose::Planar(pose.x(), pose.y(), pose.rotation());
}

void CheckSharedOptions(double resolution, double l2_max, const std::string& strategy,
                        const std::string& compression_algorithm, int patch_size, const ScanOptions& scan) {
  if (!(resolution > 0)) throw InputError("parameter resolution: expected a cell size > 0");
  if (!(l2_max > 0)) throw InputError("parameter l2_max: expected a distance > 0");
  if (strategy != "gn" && strategy != "lm") {
    throw InputError("parameter strategy: expected gn (Gauss-Newton) or lm (Levenberg-Marquardt), got '" + strategy +
                     "'");
  }
  if (compression_algorithm != "lz4" && compression_algorithm != "zstd") {
    throw InputError("parameter compression_algorithm: expected lz4 or zstd, got '" + compression_algorithm + "'");
  }
  if (patch_size < 1) throw InputError("parameter patch_size: expected at least 1 cell");
  if (scan.mrange < 0) throw InputError("parameter mrange: expected >= 0 (0: the scan's maximum range)");
  if (scan.beam_step < 1) throw InputError("parameter beam_step: expected at least 1");
}

}  // namespace slamsweep::slam::lama_driver
