#pragma once

#include <Eigen/Geometry>

namespace slamsweep::evaluator::inline core {

/// A rigid-body pose: position in metres and a unit quaternion. Planar (SE(2)) poses
/// are the special case z = 0 with a rotation about +z; every metric works on the
/// SE(3) form, as evo does, so 2D and 3D results are comparable.
struct Pose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();

  /// SE(2) pose (x, y, yaw) embedded in SE(3).
  static Pose Planar(double x_m, double y_m, double yaw_rad);
  static Pose FromIsometry(const Eigen::Isometry3d& transform);

  Eigen::Isometry3d ToIsometry() const;
  /// Heading about +z in (-pi, pi]; meaningful for planar poses.
  double Yaw() const;
  Pose Inverse() const;
  Pose operator*(const Pose& other) const;
  /// True when every component is finite and the quaternion has unit norm (1e-6).
  bool IsValid() const;
};

/// Angle of a rotation in [0, pi] (radians), stable for tiny angles.
double RotationAngleRad(const Eigen::Quaterniond& rotation);

/// a^-1 * b: the pose of b in the frame of a.
Pose Relative(const Pose& a, const Pose& b);

double RadToDeg(double rad);
double DegToRad(double deg);
/// Wraps an angle to (-pi, pi].
double NormalizeAngleRad(double angle_rad);

}  // namespace slamsweep::evaluator::inline core
