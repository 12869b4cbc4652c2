#include "evaluator/formats/trajectory/euler_angles.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "tests/evaluator/formats/trajectory/trajectory_test_util.h"

namespace slamsweep::evaluator {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2.0;

TEST(EulerAnglesTest, YawAloneTurnsXIntoY) {
  const Eigen::Quaterniond q = QuaternionFromRollPitchYaw({.roll_rad = 0.0, .pitch_rad = 0.0, .yaw_rad = kHalfPi});
  EXPECT_TRUE((q * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), 1e-15));
}

TEST(EulerAnglesTest, RollIsAppliedFirstAboutTheFixedXAxis) {
  // R = Rz(90) Ry(0) Rx(90): y -> (Rx) z -> (Rz) z, and x -> x -> y. The reverse order
  // (Rx Rz) would send y to -x instead, so this pins the convention.
  const Eigen::Quaterniond q = QuaternionFromRollPitchYaw({.roll_rad = kHalfPi, .pitch_rad = 0.0, .yaw_rad = kHalfPi});
  EXPECT_TRUE((q * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitZ(), 1e-15));
  EXPECT_TRUE((q * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), 1e-15));
}

TEST(EulerAnglesTest, PitchTurnsXDownwards) {
  // A positive rotation about +y sends +x to -z.
  const Eigen::Quaterniond q = QuaternionFromRollPitchYaw({.roll_rad = 0.0, .pitch_rad = kHalfPi, .yaw_rad = 0.0});
  EXPECT_TRUE((q * Eigen::Vector3d::UnitX()).isApprox(-Eigen::Vector3d::UnitZ(), 1e-15));
}

TEST(EulerAnglesTest, AnglesComeBackFromTheQuaternion) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(-3.1, 3.1);
  std::uniform_real_distribution<double> pitch(-1.5, 1.5);
  for (int i = 0; i < 1000; ++i) {
    const RollPitchYaw in{.roll_rad = angle(random), .pitch_rad = pitch(random), .yaw_rad = angle(random)};
    const RollPitchYaw out = RollPitchYawFromQuaternion(QuaternionFromRollPitchYaw(in));
    EXPECT_NEAR(out.roll_rad, in.roll_rad, 1e-12);
    EXPECT_NEAR(out.pitch_rad, in.pitch_rad, 1e-12);
    EXPECT_NEAR(out.yaw_rad, in.yaw_rad, 1e-12);
  }
}

TEST(EulerAnglesTest, GimbalLockStillGivesTheSameRotation) {
  const Eigen::Quaterniond q = QuaternionFromRollPitchYaw({.roll_rad = 0.3, .pitch_rad = kHalfPi, .yaw_rad = 0.2});
  const Eigen::Quaterniond back = QuaternionFromRollPitchYaw(RollPitchYawFromQuaternion(q));
  EXPECT_LT(testing_util::AngleBetweenRad(q, back), 1e-9);
}

}  // namespace
}  // namespace slamsweep::evaluator
