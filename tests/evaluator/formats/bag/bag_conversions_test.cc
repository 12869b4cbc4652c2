#include "evaluator/formats/bag/bag_conversions.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

TEST(BagConversionsTest, NonFiniteRangesBecomeNoReturn) {
  BagScan scan;
  scan.stamp_s = 3.0;
  scan.range_min_m = 0.5f;
  scan.range_max_m = 8.0f;
  scan.angle_min_rad = -1.0f;
  scan.angle_increment_rad = 0.5f;
  const float inf = std::numeric_limits<float>::infinity();
  scan.ranges_m = {1.0f, std::numeric_limits<float>::quiet_NaN(), inf, -inf, 0.25f};
  const LaserScan out = ToLaserScan(scan);
  EXPECT_EQ(out.ranges_m, (std::vector<float>{1.0f, 8.0f, 8.0f, 8.0f, 0.25f}));
  EXPECT_TRUE(out.IsHit(out.ranges_m[0]));
  EXPECT_FALSE(out.IsHit(out.ranges_m[1]));
  EXPECT_FALSE(out.IsHit(out.ranges_m[4]));  // below range_min stays as recorded, and is no hit
  EXPECT_EQ(out.stamp_s, 3.0);
  EXPECT_EQ(out.angle_min_rad, -1.0);
  EXPECT_EQ(out.angle_increment_rad, 0.5);
}

// A LaserScan stores its fan in float32. The float rounding of a CARMEN SICK layout's fan for the beam count
// (180 beams: -90 deg in 1 deg steps) is that fan in double; any other float fan stays as stored.
TEST(BagConversionsTest, AFloatRoundedSickFanIsTheSickFan) {
  BagScan scan;
  scan.range_max_m = 80.0f;
  scan.ranges_m.assign(180, 2.0f);
  const double pi = std::acos(-1.0);
  scan.angle_min_rad = static_cast<float>(-pi / 2);
  scan.angle_increment_rad = static_cast<float>(pi / 180);
  ASSERT_NE(static_cast<double>(scan.angle_increment_rad), pi / 180);
  const LaserScan sick = ToLaserScan(scan);
  EXPECT_EQ(sick.angle_min_rad, -pi / 2);
  EXPECT_EQ(sick.angle_increment_rad, pi / 180);
  scan.ranges_m.assign(181, 2.0f);  // 181 beams cover -90..+90 deg in pi / 180 steps too
  EXPECT_EQ(ToLaserScan(scan).angle_increment_rad, pi / 180);
  scan.ranges_m.assign(179, 2.0f);  // no SICK layout: as stored
  EXPECT_EQ(ToLaserScan(scan).angle_increment_rad, static_cast<double>(static_cast<float>(pi / 180)));
  scan.ranges_m.assign(180, 2.0f);
  scan.angle_min_rad = std::nextafter(scan.angle_min_rad, 0.0f);  // a float away from the layout: as stored
  EXPECT_EQ(ToLaserScan(scan).angle_min_rad, static_cast<double>(scan.angle_min_rad));
  EXPECT_EQ(ToLaserScan(scan).angle_increment_rad, static_cast<double>(static_cast<float>(pi / 180)));
}

TEST(BagConversionsTest, ZeroStampFallsBackToRecordTime) {
  EXPECT_EQ(MessageStamp(0.0, 7.5), 7.5);
  EXPECT_EQ(MessageStamp(2.0, 7.5), 2.0);
}

TEST(BagConversionsTest, PoseIsNormalisedAndProjected) {
  // Quaternion (0, 0, 2, 2): 90 degrees about z, twice too long; z and tilt are dropped.
  const Pose pose = ToPlanarPose(BagPose{1.0, 2.0, 3.0, 0.0, 0.0, 2.0, 2.0}, "here");
  EXPECT_NEAR(pose.Yaw(), std::acos(0.0), 1e-12);
  EXPECT_EQ(pose.position.z(), 0.0);
  EXPECT_EQ(pose.position.x(), 1.0);
  EXPECT_TRUE(pose.IsValid());
}

TEST(BagConversionsTest, UnusablePosesNameTheirPlace) {
  EXPECT_THAT(
      [] {
        ToPlanarPose(BagPose{0, 0, 0, 0, 0, 0, 0}, "bag.bag: topic '/odom' message 3");
      },
      ::testing::ThrowsMessage<InputError>(AllOf(HasSubstr("topic '/odom' message 3"), HasSubstr("zero norm"))));
  EXPECT_THAT(
      [] {
        ToPlanarPose(BagPose{std::nan(""), 0, 0, 0, 0, 0, 1}, "where");
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("where: pose has a non-finite component")));
}

TEST(BagConversionsTest, TrajectoryIsSortedAndDropsRepeatedStamps) {
  std::vector<BagStampedPose> poses(3);
  poses[0].stamp_s = 2.0;
  poses[0].pose.x_m = 2.0;
  poses[1].stamp_s = 1.0;
  poses[1].pose.x_m = 1.0;
  poses[2].stamp_s = 2.0;
  poses[2].pose.x_m = 9.0;
  std::size_t dropped = 0;
  const Trajectory trajectory = ToTrajectory(poses, "b.bag", "/odom", dropped);
  EXPECT_EQ(trajectory.stamps_s(), (std::vector<double>{1.0, 2.0}));
  EXPECT_EQ(trajectory.poses()[1].position.x(), 2.0);  // the first message with that stamp wins
  EXPECT_EQ(dropped, 1u);
}

}  // namespace
}  // namespace slamsweep::evaluator
