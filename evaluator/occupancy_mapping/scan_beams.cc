#include "evaluator/occupancy_mapping/scan_beams.h"

#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline occupancy_mapping {

void ValidateScanGeometry(const LaserScan& scan, std::size_t scan_index) {
  const std::string where = "scan " + std::to_string(scan_index) + ": ";
  if (!std::isfinite(scan.angle_min_rad) || !std::isfinite(scan.angle_increment_rad)) {
    throw InputError(where + "angle_min_rad and angle_increment_rad must be finite");
  }
  if (!std::isfinite(scan.range_min_m) || scan.range_min_m < 0.0) {
    throw InputError(where + "range_min_m = " + std::to_string(scan.range_min_m) + ", expected a finite number >= 0");
  }
  if (!(scan.range_max_m > scan.range_min_m)) {
    throw InputError(where + "range_max_m = " + std::to_string(scan.range_max_m) +
                     ", expected > range_min_m = " + std::to_string(scan.range_min_m));
  }
  if (!scan.sensor_pose_on_robot.IsValid()) throw InputError(where + "sensor_pose_on_robot is not a valid pose");
}

SensorPose2d SensorInWorld(const Pose& robot_pose, const LaserScan& scan) {
  const Pose sensor = robot_pose * scan.sensor_pose_on_robot;
  return {sensor.position.x(), sensor.position.y(), sensor.Yaw()};
}

void BeamDirections::Update(const LaserScan& scan) {
  if (cos_.size() == scan.BeamCount() && angle_min_rad_ == scan.angle_min_rad &&
      angle_increment_rad_ == scan.angle_increment_rad) {
    return;
  }
  angle_min_rad_ = scan.angle_min_rad;
  angle_increment_rad_ = scan.angle_increment_rad;
  cos_.resize(scan.BeamCount());
  sin_.resize(scan.BeamCount());
  for (std::size_t i = 0; i < scan.BeamCount(); ++i) {
    cos_[i] = std::cos(scan.BeamAngleRad(i));
    sin_[i] = std::sin(scan.BeamAngleRad(i));
  }
}

}  // namespace slamsweep::evaluator::inline occupancy_mapping
