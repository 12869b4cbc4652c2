#include "evaluator/core/pose.h"

#include <cmath>
#include <numbers>

namespace slamsweep::evaluator::inline core {

Pose Pose::Planar(double x_m, double y_m, double yaw_rad) {
  Pose pose;
  pose.position = Eigen::Vector3d(x_m, y_m, 0.0);
  pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()));
  return pose;
}

Pose Pose::FromIsometry(const Eigen::Isometry3d& transform) {
  Pose pose;
  pose.position = transform.translation();
  pose.orientation = Eigen::Quaterniond(transform.rotation()).normalized();
  return pose;
}

Eigen::Isometry3d Pose::ToIsometry() const {
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.linear() = orientation.toRotationMatrix();
  transform.translation() = position;
  return transform;
}

double Pose::Yaw() const {
  const Eigen::Quaterniond& q = orientation;
  return std::atan2(2.0 * (q.w() * q.z() + q.x() * q.y()), 1.0 - 2.0 * (q.y() * q.y() + q.z() * q.z()));
}

Pose Pose::Inverse() const {
  Pose inverse;
  inverse.orientation = orientation.conjugate();
  inverse.position = -(inverse.orientation * position);
  return inverse;
}

Pose Pose::operator*(const Pose& other) const {
  Pose composed;
  composed.orientation = orientation * other.orientation;
  composed.position = position + orientation * other.position;
  return composed;
}

bool Pose::IsValid() const {
  return position.allFinite() && orientation.coeffs().allFinite() && std::abs(orientation.norm() - 1.0) < 1e-6;
}

double RotationAngleRad(const Eigen::Quaterniond& rotation) {
  // atan2 of the vector and scalar parts keeps precision near 0 and pi, where acos(w) does not.
  return 2.0 * std::atan2(rotation.vec().norm(), std::abs(rotation.w()));
}

Pose Relative(const Pose& a, const Pose& b) { return a.Inverse() * b; }

double RadToDeg(double rad) { return rad * 180.0 / std::numbers::pi; }
double DegToRad(double deg) { return deg * std::numbers::pi / 180.0; }

double NormalizeAngleRad(double angle_rad) {
  double wrapped = std::remainder(angle_rad, 2.0 * std::numbers::pi);
  if (wrapped <= -std::numbers::pi) wrapped += 2.0 * std::numbers::pi;
  return wrapped;
}

}  // namespace slamsweep::evaluator::inline core
