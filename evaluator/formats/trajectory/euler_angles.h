#pragma once

#include <Eigen/Geometry>

namespace slamsweep::evaluator::inline formats::inline trajectory {

/// Roll, pitch and yaw (radians) of R = Rz(yaw) * Ry(pitch) * Rx(roll): rotations about the
/// fixed X, then Y, then Z axes. Kuemmerle relations files and MRPT's CPose3D (yaw, pitch,
/// roll) both use this convention, so one conversion serves both formats.
struct RollPitchYaw {
  double roll_rad = 0.0;
  double pitch_rad = 0.0;
  double yaw_rad = 0.0;
};

Eigen::Quaterniond QuaternionFromRollPitchYaw(const RollPitchYaw& angles);

/// The inverse of QuaternionFromRollPitchYaw, with pitch in [-pi/2, pi/2]. At pitch = +-pi/2
/// (gimbal lock) only roll -/+ yaw is defined; yaw is then reported as 0.
RollPitchYaw RollPitchYawFromQuaternion(const Eigen::Quaterniond& rotation);

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
