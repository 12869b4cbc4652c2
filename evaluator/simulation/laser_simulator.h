#pragma once

#include <numbers>
#include <string>

#include <nlohmann/json.hpp>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/occupancy_grid.h"
#include "evaluator/core/pose.h"

namespace slamsweep::evaluator::inline simulation {

/// A simulated planar laser scanner. Beams are spread evenly over fov_rad, centred on the
/// sensor's +x axis; a full circle (fov_rad = 2 pi) has no duplicated beam at the seam.
struct LaserOptions {
  int beam_count = 360;
  double fov_rad = 2.0 * std::numbers::pi;
  double range_min_m = 0.05;
  double range_max_m = 20.0;
  /// Mounting of the sensor on the robot (planar).
  Pose sensor_pose_on_robot;

  bool operator==(const LaserOptions& other) const;
};

/// Throws InputError naming the option unless beam_count is in [1, 100000], 0 < fov_rad <= 2 pi,
/// 0 <= range_min_m < range_max_m (finite) and the mounting is a valid planar pose.
void ValidateLaserOptions(const LaserOptions& options);

/// Distance from (x_m, y_m) along direction_rad to the first occupied cell (p >= 0.5) of
/// `map`, measured to the cell's border, or a negative number when nothing is hit within
/// max_range_m. Unknown cells are transparent; a ray that leaves the grid hits nothing. A start
/// inside an occupied cell gives 0. Exact cell traversal (Amanatides and Woo), no sampling.
double CastRay(const OccupancyGrid& map, double x_m, double y_m, double direction_rad, double max_range_m);

/// The noise-free scan seen from `robot_pose` (planar) at time stamp_s: ranges as CastRay
/// gives them; beams without a hit hold the no-return value (>= range_max_m).
LaserScan SimulateScan(const OccupancyGrid& map, const Pose& robot_pose, double stamp_s, const LaserOptions& options);

void to_json(nlohmann::json& out, const LaserOptions& options);
/// Strict reader (see JsonFields); the mounting is read as sensor_x_m, sensor_y_m, sensor_yaw_rad.
LaserOptions LaserOptionsFromJson(const nlohmann::json& in, const std::string& path = "laser");

}  // namespace slamsweep::evaluator::inline simulation
