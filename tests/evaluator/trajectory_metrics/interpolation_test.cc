#include "evaluator/trajectory_metrics/interpolation.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

TEST(InterpolationTest, MidpointIsHalfwayInPositionAndHeading) {
  const Pose a = Pose::Planar(0.0, 0.0, 0.0);
  Pose b = Pose::Planar(2.0, 4.0, std::numbers::pi / 2.0);
  b.position.z() = 6.0;
  const Pose mid = InterpolatePose(a, b, 0.5);
  EXPECT_NEAR(mid.position.x(), 1.0, 1e-12);
  EXPECT_NEAR(mid.position.y(), 2.0, 1e-12);
  EXPECT_NEAR(mid.position.z(), 3.0, 1e-12);
  EXPECT_NEAR(mid.Yaw(), std::numbers::pi / 4.0, 1e-12);
  EXPECT_NEAR(InterpolatePose(a, b, 0.25).Yaw(), std::numbers::pi / 8.0, 1e-12);
}

TEST(InterpolationTest, RotationTakesTheShorterArc) {
  // From +170 to -170 degrees the short way passes through 180, not through 0.
  const Pose a = Pose::Planar(0.0, 0.0, DegToRad(170.0));
  const Pose b = Pose::Planar(0.0, 0.0, DegToRad(-170.0));
  EXPECT_NEAR(std::abs(InterpolatePose(a, b, 0.5).Yaw()), std::numbers::pi, 1e-12);
  // q and -q are the same rotation: the sign of the stored quaternion must not matter.
  Pose flipped = Pose::Planar(0.0, 0.0, DegToRad(40.0));
  flipped.orientation.coeffs() = -flipped.orientation.coeffs();
  EXPECT_NEAR(InterpolatePose(Pose::Planar(0, 0, 0), flipped, 0.5).Yaw(), DegToRad(20.0), 1e-12);
}

Trajectory ThreePoses() {
  Trajectory trajectory;
  trajectory.Add(10.0, Pose::Planar(0.0, 0.0, 0.0));
  trajectory.Add(12.0, Pose::Planar(2.0, 0.0, 0.0));
  trajectory.Add(14.0, Pose::Planar(2.0, 4.0, 0.0));
  return trajectory;
}

TEST(InterpolationTest, TrajectoryLookupInterpolatesInsideAndRefusesOutside) {
  const Trajectory trajectory = ThreePoses();
  const TrajectoryInterpolator interpolator(trajectory);
  EXPECT_NEAR(interpolator.At(11.0)->position.x(), 1.0, 1e-12);
  EXPECT_NEAR(interpolator.At(13.5)->position.y(), 3.0, 1e-12);
  // Recorded stamps, including both ends, give the recorded poses.
  EXPECT_EQ(interpolator.At(10.0)->position, Eigen::Vector3d(0.0, 0.0, 0.0));
  EXPECT_EQ(interpolator.At(12.0)->position, Eigen::Vector3d(2.0, 0.0, 0.0));
  EXPECT_EQ(interpolator.At(14.0)->position, Eigen::Vector3d(2.0, 4.0, 0.0));
  EXPECT_FALSE(interpolator.At(9.999).has_value());
  EXPECT_FALSE(interpolator.At(14.001).has_value());
}

TEST(InterpolationTest, DecreasingStampsAndEmptyTrajectoriesAreInputErrors) {
  Trajectory trajectory = ThreePoses();
  trajectory.Add(13.0, Pose::Planar(0.0, 0.0, 0.0));
  try {
    TrajectoryInterpolator interpolator(trajectory);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("pose 3"));
    EXPECT_THAT(error.what(), HasSubstr("non-decreasing"));
  }
  const Trajectory empty;
  EXPECT_THROW(TrajectoryInterpolator{empty}, InputError);
}

TEST(OdometryInterpolatorTest, ATurnOnTheSpotBetweenKeyframesKeepsTurning) {
  // Keyframes at t = 0 and t = 2, both at the origin facing +x: between them the robot turned a full
  // circle on the spot. Linear interpolation says it never turned; the odometry says at t = 1 it
  // faced -x. The estimate is offset by (10, 0) from the odometry: the odometry's motion is applied
  // to the estimate's pose, not its absolute pose.
  Trajectory estimate;
  estimate.Add(0.0, Pose::Planar(10.0, 0.0, 0.0));
  estimate.Add(2.0, Pose::Planar(10.0, 0.0, 0.0));
  Trajectory odometry;
  for (int i = 0; i <= 8; ++i) odometry.Add(0.25 * i, Pose::Planar(0.0, 0.0, std::numbers::pi / 4.0 * i));
  const OdometryInterpolator by_odometry(estimate, odometry);
  bool fallback = true;
  const std::optional<Pose> at_one = by_odometry.At(1.0, &fallback);
  ASSERT_TRUE(at_one.has_value());
  EXPECT_FALSE(fallback);
  EXPECT_NEAR(std::abs(at_one->Yaw()), std::numbers::pi, 1e-9);
  EXPECT_NEAR(at_one->position.x(), 10.0, 1e-9);
  // Between two readings the odometry itself is interpolated: t = 0.125 is half of the first 45 deg.
  EXPECT_NEAR(by_odometry.At(0.125)->Yaw(), std::numbers::pi / 8.0, 1e-9);
  // At an estimate stamp, the estimate's own pose; outside its span, nothing.
  EXPECT_NEAR(by_odometry.At(2.0)->Yaw(), 0.0, 1e-12);
  EXPECT_FALSE(by_odometry.At(2.5).has_value());
  EXPECT_FALSE(by_odometry.At(-0.1).has_value());
  // The linear interpolator never turns.
  EXPECT_NEAR(TrajectoryInterpolator(estimate).At(1.0)->Yaw(), 0.0, 1e-12);
}

TEST(OdometryInterpolatorTest, OdometryThatDoesNotCoverTheTimeFallsBackToLinear) {
  Trajectory estimate;
  estimate.Add(0.0, Pose::Planar(0.0, 0.0, 0.0));
  estimate.Add(2.0, Pose::Planar(2.0, 0.0, 0.0));
  Trajectory odometry;
  odometry.Add(0.5, Pose::Planar(0.0, 0.0, 0.0));
  odometry.Add(1.5, Pose::Planar(5.0, 0.0, 0.0));
  const OdometryInterpolator by_odometry(estimate, odometry);
  bool fallback = false;
  const std::optional<Pose> pose = by_odometry.At(1.0, &fallback);
  ASSERT_TRUE(pose.has_value());
  EXPECT_TRUE(fallback);
  EXPECT_NEAR(pose->position.x(), 1.0, 1e-12);
}

}  // namespace
}  // namespace slamsweep::evaluator
