#include "evaluator/core/pose.h"

#include <gtest/gtest.h>

#include <numbers>

namespace slamsweep::evaluator {
namespace {

TEST(PoseTest, PlanarPoseKeepsYawAndPosition) {
  const Pose pose = Pose::Planar(1.5, -2.0, 2.5);
  EXPECT_DOUBLE_EQ(pose.position.x(), 1.5);
  EXPECT_DOUBLE_EQ(pose.position.y(), -2.0);
  EXPECT_DOUBLE_EQ(pose.position.z(), 0.0);
  EXPECT_NEAR(pose.Yaw(), 2.5, 1e-12);
}

TEST(PoseTest, ComposeWithInverseIsIdentity) {
  Pose pose;
  pose.position = {1.0, 2.0, 3.0};
  pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  const Pose identity = pose * pose.Inverse();
  EXPECT_NEAR(identity.position.norm(), 0.0, 1e-12);
  EXPECT_NEAR(RotationAngleRad(identity.orientation), 0.0, 1e-12);
}

TEST(PoseTest, RelativePoseOfPlanarPoses) {
  // b is 1 m ahead of a, with a facing +y: in a's frame b is at (1, 0), turned by 0.5 rad.
  const Pose a = Pose::Planar(2.0, 3.0, std::numbers::pi / 2);
  const Pose b = Pose::Planar(2.0, 4.0, std::numbers::pi / 2 + 0.5);
  const Pose r = Relative(a, b);
  EXPECT_NEAR(r.position.x(), 1.0, 1e-12);
  EXPECT_NEAR(r.position.y(), 0.0, 1e-12);
  EXPECT_NEAR(r.Yaw(), 0.5, 1e-12);
}

TEST(PoseTest, RotationAngleIsInZeroToPi) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(1.2, Eigen::Vector3d::UnitX()));
  EXPECT_NEAR(RotationAngleRad(q), 1.2, 1e-12);
  // The same rotation with a negated quaternion.
  EXPECT_NEAR(RotationAngleRad(Eigen::Quaterniond(-q.coeffs())), 1.2, 1e-12);
  EXPECT_NEAR(RotationAngleRad(Eigen::Quaterniond(Eigen::AngleAxisd(1e-9, Eigen::Vector3d::UnitZ()))), 1e-9, 1e-20);
}

TEST(PoseTest, NormalizeAngleWrapsIntoHalfOpenInterval) {
  EXPECT_NEAR(NormalizeAngleRad(3 * std::numbers::pi), std::numbers::pi, 1e-12);
  EXPECT_NEAR(NormalizeAngleRad(-std::numbers::pi), std::numbers::pi, 1e-12);
  EXPECT_NEAR(NormalizeAngleRad(0.25 - 4 * std::numbers::pi), 0.25, 1e-12);
}

TEST(PoseTest, InvalidPosesAreDetected) {
  Pose nan_pose;
  nan_pose.position.x() = std::nan("");
  EXPECT_FALSE(nan_pose.IsValid());
  Pose scaled;
  scaled.orientation.coeffs() *= 2.0;
  EXPECT_FALSE(scaled.IsValid());
  EXPECT_TRUE(Pose::Planar(0, 0, 1).IsValid());
}

}  // namespace
}  // namespace slamsweep::evaluator
