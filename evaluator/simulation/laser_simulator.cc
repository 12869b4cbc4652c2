#include "evaluator/simulation/laser_simulator.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "evaluator/core/input_error.h"
#include "evaluator/noise/json_fields.h"
#include "evaluator/noise/range_noise.h"

namespace slamsweep::evaluator::inline simulation {
namespace {

constexpr double kFullCircle = 2.0 * std::numbers::pi;

void CheckOptions(const LaserOptions& o, const std::string& prefix) {
  if (o.beam_count < 1 || o.beam_count > 100000) {
    throw InputError(prefix + "beam_count = " + std::to_string(o.beam_count) + ", expected in [1, 100000]");
  }
  if (!(std::isfinite(o.fov_rad) && o.fov_rad > 0.0 && o.fov_rad <= kFullCircle + 1e-9)) {
    throw InputError(prefix + "fov_rad = " + std::to_string(o.fov_rad) + ", expected in (0, 2 pi]");
  }
  if (!(std::isfinite(o.range_min_m) && o.range_min_m >= 0.0)) {
    throw InputError(prefix + "range_min_m = " + std::to_string(o.range_min_m) + ", expected a finite number >= 0");
  }
  if (!(std::isfinite(o.range_max_m) && o.range_max_m > o.range_min_m)) {
    throw InputError(prefix + "range_max_m = " + std::to_string(o.range_max_m) + ", expected finite and > range_min_m");
  }
  if (!o.sensor_pose_on_robot.IsValid()) throw InputError(prefix + "sensor pose on the robot is not a valid pose");
}

bool Occupied(const OccupancyGrid& map, int col, int cell_y) {
  const float p = map.at(map.height - 1 - cell_y, col);
  return p >= 0.5f;
}

}  // namespace

bool LaserOptions::operator==(const LaserOptions& other) const {
  return beam_count == other.beam_count && fov_rad == other.fov_rad && range_min_m == other.range_min_m &&
         range_max_m == other.range_max_m && sensor_pose_on_robot.position == other.sensor_pose_on_robot.position &&
         sensor_pose_on_robot.orientation.coeffs() == other.sensor_pose_on_robot.orientation.coeffs();
}

void ValidateLaserOptions(const LaserOptions& options) { CheckOptions(options, "laser option "); }

double CastRay(const OccupancyGrid& map, double x_m, double y_m, double direction_rad, double max_range_m) {
  // Cell coordinates with y upwards: cell (col, cell_y) is map row height - 1 - cell_y.
  const double x = (x_m - map.origin.x_m) / map.resolution_m;
  const double y = (y_m - map.origin.y_m) / map.resolution_m;
  if (!(x >= 0.0 && x < map.width && y >= 0.0 && y < map.height)) return -1.0;
  int col = static_cast<int>(x);
  int cell_y = static_cast<int>(y);
  const double dx = std::cos(direction_rad);
  const double dy = std::sin(direction_rad);
  const int step_x = dx > 0.0 ? 1 : -1;
  const int step_y = dy > 0.0 ? 1 : -1;
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  // Ray parameter (in cells travelled) at which the next vertical / horizontal border is crossed.
  double next_x = dx != 0.0 ? ((dx > 0.0 ? col + 1 : col) - x) / dx : kInfinity;
  double next_y = dy != 0.0 ? ((dy > 0.0 ? cell_y + 1 : cell_y) - y) / dy : kInfinity;
  const double delta_x = dx != 0.0 ? std::abs(1.0 / dx) : kInfinity;
  const double delta_y = dy != 0.0 ? std::abs(1.0 / dy) : kInfinity;
  const double limit = max_range_m / map.resolution_m;
  double travelled = 0.0;
  while (true) {
    if (Occupied(map, col, cell_y)) return travelled * map.resolution_m;
    if (next_x < next_y) {
      travelled = next_x;
      next_x += delta_x;
      col += step_x;
    } else {
      travelled = next_y;
      next_y += delta_y;
      cell_y += step_y;
    }
    if (travelled > limit || col < 0 || col >= map.width || cell_y < 0 || cell_y >= map.height) return -1.0;
  }
}

LaserScan SimulateScan(const OccupancyGrid& map, const Pose& robot_pose, double stamp_s, const LaserOptions& options) {
  ValidateLaserOptions(options);
  LaserScan scan;
  scan.stamp_s = stamp_s;
  scan.range_min_m = options.range_min_m;
  scan.range_max_m = options.range_max_m;
  scan.sensor_pose_on_robot = options.sensor_pose_on_robot;
  const bool full_circle = options.fov_rad >= kFullCircle - 1e-9;
  const int gaps = full_circle || options.beam_count == 1 ? options.beam_count : options.beam_count - 1;
  scan.angle_increment_rad = options.fov_rad / gaps;
  scan.angle_min_rad = options.beam_count == 1 ? 0.0 : -0.5 * options.fov_rad;

  const Pose sensor = robot_pose * options.sensor_pose_on_robot;
  const double yaw = sensor.Yaw();
  const float no_return = NoReturnRangeM(options.range_max_m);
  scan.ranges_m.resize(static_cast<std::size_t>(options.beam_count));
  for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const double range =
        CastRay(map, sensor.position.x(), sensor.position.y(), yaw + scan.BeamAngleRad(i), options.range_max_m);
    scan.ranges_m[i] = range < 0.0 || range >= options.range_max_m ? no_return : static_cast<float>(range);
  }
  return scan;
}

void to_json(nlohmann::json& out, const LaserOptions& o) {
  out = nlohmann::json{{"beam_count", o.beam_count},
                       {"fov_rad", o.fov_rad},
                       {"range_min_m", o.range_min_m},
                       {"range_max_m", o.range_max_m},
                       {"sensor_x_m", o.sensor_pose_on_robot.position.x()},
                       {"sensor_y_m", o.sensor_pose_on_robot.position.y()},
                       {"sensor_yaw_rad", o.sensor_pose_on_robot.Yaw()}};
}

LaserOptions LaserOptionsFromJson(const nlohmann::json& in, const std::string& path) {
  JsonFields fields(in, path);
  LaserOptions o;
  o.beam_count = fields.Integer("beam_count", o.beam_count);
  o.fov_rad = fields.Number("fov_rad", o.fov_rad);
  o.range_min_m = fields.Number("range_min_m", o.range_min_m);
  o.range_max_m = fields.Number("range_max_m", o.range_max_m);
  const double sensor_x = fields.Number("sensor_x_m", 0.0);
  const double sensor_y = fields.Number("sensor_y_m", 0.0);
  const double sensor_yaw = fields.Number("sensor_yaw_rad", 0.0);
  o.sensor_pose_on_robot = Pose::Planar(sensor_x, sensor_y, sensor_yaw);
  fields.Finish();
  CheckOptions(o, path + ".");
  return o;
}

}  // namespace slamsweep::evaluator::inline simulation
