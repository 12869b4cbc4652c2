#include "evaluator/formats/trajectory/euler_angles.h"

#include <cmath>

namespace slamsweep::evaluator::inline formats::inline trajectory {

Eigen::Quaterniond QuaternionFromRollPitchYaw(const RollPitchYaw& angles) {
  const Eigen::Quaterniond rotation = Eigen::AngleAxisd(angles.yaw_rad, Eigen::Vector3d::UnitZ()) *
                                      Eigen::AngleAxisd(angles.pitch_rad, Eigen::Vector3d::UnitY()) *
                                      Eigen::AngleAxisd(angles.roll_rad, Eigen::Vector3d::UnitX());
  return rotation.normalized();
}

RollPitchYaw RollPitchYawFromQuaternion(const Eigen::Quaterniond& rotation) {
  const Eigen::Matrix3d r = rotation.normalized().toRotationMatrix();
  RollPitchYaw angles;
  const double cos_pitch = std::hypot(r(0, 0), r(1, 0));
  // atan2 instead of asin(-r20): asin loses half its digits near +-pi/2.
  angles.pitch_rad = std::atan2(-r(2, 0), cos_pitch);
  if (cos_pitch > 1e-12) {
    angles.yaw_rad = std::atan2(r(1, 0), r(0, 0));
    angles.roll_rad = std::atan2(r(2, 1), r(2, 2));
  } else {
    // With yaw = 0, R = Ry(pitch) Rx(roll), whose second row is (0, cos roll, -sin roll).
    angles.yaw_rad = 0.0;
    angles.roll_rad = std::atan2(-r(1, 2), r(1, 1));
  }
  return angles;
}

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
