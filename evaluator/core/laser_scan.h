#pragma once

#include <cstddef>
#include <vector>

#include "evaluator/core/pose.h"

namespace slamsweep::evaluator::inline core {

/// One 2D laser scan. Beam i points at angle_min_rad + i * angle_increment_rad in the sensor
/// frame (counter-clockwise, 0 = sensor +x). A range outside [range_min_m, range_max_m) is
/// "no return" (CARMEN and MRPT store max range for it); mappers clear space up to max range
/// for such beams but do not mark an obstacle.
struct LaserScan {
  double stamp_s = 0.0;
  std::vector<float> ranges_m;
  double angle_min_rad = 0.0;
  double angle_increment_rad = 0.0;
  double range_min_m = 0.0;
  double range_max_m = 0.0;
  /// Pose of the sensor on the robot (planar); identity when the sensor sits at the robot origin.
  Pose sensor_pose_on_robot;

  std::size_t BeamCount() const { return ranges_m.size(); }
  double BeamAngleRad(std::size_t index) const {
    return angle_min_rad + static_cast<double>(index) * angle_increment_rad;
  }
  bool IsHit(float range_m) const { return range_m >= range_min_m && range_m < range_max_m; }
};

}  // namespace slamsweep::evaluator::inline core
