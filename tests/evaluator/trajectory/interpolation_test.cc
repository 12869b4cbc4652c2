#include "evaluator/trajectory/interpolation.h"

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

}  // namespace
}  // namespace slamsweep::evaluator
