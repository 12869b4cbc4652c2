#include "tests/evaluator/sequence/room_scan.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace slamsweep::evaluator::testing {

LaserScan RoomScan(const Pose& robot) {
  LaserScan scan;
  scan.angle_min_rad = -std::numbers::pi / 2.0;
  scan.angle_increment_rad = std::numbers::pi / 360.0;
  scan.range_min_m = 0.0;
  scan.range_max_m = 30.0;
  const double x0 = robot.position.x();
  const double y0 = robot.position.y();
  for (int b = 0; b < 361; ++b) {
    const double angle = robot.Yaw() + scan.BeamAngleRad(static_cast<std::size_t>(b));
    const double dx = std::cos(angle);
    const double dy = std::sin(angle);
    double range = 30.0;
    for (const double wall_x : {-1.0, 5.0}) {
      const double t = (wall_x - x0) / dx;
      if (t > 0 && std::abs(y0 + t * dy) <= 2.0) range = std::min(range, t);
    }
    for (const double wall_y : {-2.0, 2.0}) {
      const double t = (wall_y - y0) / dy;
      if (t > 0 && std::abs(x0 + t * dx) <= 5.0) range = std::min(range, t);
    }
    // The pillar's face toward the robot's usual side, x = 2.8.
    const double t = (2.8 - x0) / dx;
    if (t > 0 && std::abs(y0 + t * dy - 1.0) <= 0.2) range = std::min(range, t);
    scan.ranges_m.push_back(static_cast<float>(range));
  }
  return scan;
}

}  // namespace slamsweep::evaluator::testing
