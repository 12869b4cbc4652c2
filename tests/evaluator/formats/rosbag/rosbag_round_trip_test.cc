// Bags written with librosbag's own writer (rosbag::Bag) and read back.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/bag/bag_sequence.h"
#include "evaluator/formats/bag/bag_topics.h"
#include "evaluator/formats/rosbag/ros1_bag_io.h"
#include "evaluator/formats/rosbag/rosbag_reader.h"
#include "tests/evaluator/formats/rosbag/bag_test_writer.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

BagScan MakeScan(double stamp_s, std::vector<float> ranges_m, std::string frame = "base_link") {
  BagScan scan;
  scan.stamp_s = stamp_s;
  scan.frame_id = std::move(frame);
  scan.angle_min_rad = -2.0f;
  scan.angle_max_rad = 2.0f;
  scan.angle_increment_rad = 4.0f / static_cast<float>(ranges_m.size() - 1);
  scan.range_min_m = 0.05f;
  scan.range_max_m = 25.0f;
  scan.ranges_m = std::move(ranges_m);
  return scan;
}

BagStampedPose MakeOdometry(double stamp_s, double x_m, double y_m, double yaw_rad) {
  return BagStampedPose{stamp_s, 0.0, "odom", "base_link",
                        BagPose{x_m, y_m, 0.0, 0.0, 0.0, std::sin(yaw_rad / 2), std::cos(yaw_rad / 2)}};
}

class RosbagRoundTripTest : public ::testing::Test {
 protected:
  testing::TempDir dir_;
};

TEST_F(RosbagRoundTripTest, ScansAndOdometryAtTheSameStampsComeBackExactly) {
  const auto path = dir_ / "run.bag";
  std::mt19937 random(7);
  std::uniform_real_distribution<float> range(0.1f, 20.0f);
  std::vector<BagScan> scans;
  {
    testing::BagTestWriter writer(path);
    for (int i = 0; i < 20; ++i) {
      const double stamp_s = 1000.0 + 0.1 * i;
      std::vector<float> ranges(181);
      for (float& r : ranges) r = range(random);
      scans.push_back(MakeScan(stamp_s, ranges));
      writer.WriteScan("/base_scan", scans.back());
      writer.WriteOdometry("/odom", MakeOdometry(stamp_s, 0.5 * i, -0.25 * i, 0.05 * i - 0.5));
    }
  }
  const Sequence sequence = ReadRosbag(path);
  EXPECT_EQ(sequence.name, "run");
  EXPECT_EQ(sequence.provenance.source, path.string());
  EXPECT_TRUE(sequence.warnings.empty()) << sequence.warnings.front();
  EXPECT_FALSE(sequence.reference.has_value());
  ASSERT_EQ(sequence.scans.size(), 20u);
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const LaserScan& scan = sequence.scans[i];
    // Stamps go through ros::Time (whole nanoseconds).
    EXPECT_NEAR(scan.stamp_s, scans[i].stamp_s, 1e-9);
    EXPECT_EQ(scan.ranges_m, scans[i].ranges_m);
    EXPECT_EQ(scan.angle_min_rad, -2.0);
    EXPECT_EQ(scan.angle_increment_rad, static_cast<double>(4.0f / 180.0f));
    EXPECT_EQ(scan.range_min_m, static_cast<double>(0.05f));
    EXPECT_EQ(scan.range_max_m, 25.0);
    EXPECT_TRUE(scan.sensor_pose_on_robot.position.isZero());
    const Pose& odometry = sequence.odometry.poses()[i];
    EXPECT_EQ(sequence.odometry.stamps_s()[i], scan.stamp_s);
    EXPECT_NEAR(odometry.position.x(), 0.5 * static_cast<double>(i), 1e-12);
    EXPECT_NEAR(odometry.position.y(), -0.25 * static_cast<double>(i), 1e-12);
    EXPECT_NEAR(odometry.Yaw(), 0.05 * static_cast<double>(i) - 0.5, 1e-12);
  }
}

TEST_F(RosbagRoundTripTest, InspectListsTopicsTypesAndCounts) {
  const auto path = dir_ / "mixed.bag";
  {
    testing::BagTestWriter writer(path);
    writer.WriteText("/chatter", 5.0, "hello");
    writer.WriteScan("/scan", MakeScan(6.0, {1.0f, 2.0f}));
    writer.WriteScan("/scan", MakeScan(7.0, {1.0f, 2.0f}));
    writer.WriteOdometry("/odom", MakeOdometry(8.0, 0, 0, 0));
  }
  const BagSummary info = ReadRos1BagSummary(path);
  ASSERT_EQ(info.topics.size(), 3u);
  EXPECT_EQ(info.topics[0].topic, "/chatter");
  EXPECT_EQ(info.topics[0].datatype, "std_msgs/String");
  EXPECT_EQ(info.topics[0].message_count, 1u);
  EXPECT_EQ(info.topics[1].topic, "/odom");
  EXPECT_EQ(info.topics[1].datatype, "nav_msgs/Odometry");
  EXPECT_EQ(info.topics[2].topic, "/scan");
  EXPECT_EQ(info.topics[2].datatype, "sensor_msgs/LaserScan");
  EXPECT_EQ(info.topics[2].message_count, 2u);
  EXPECT_EQ(info.message_count, 4u);
  EXPECT_EQ(info.start_s, 5.0);
  EXPECT_EQ(info.end_s, 8.0);
  EXPECT_EQ(TopicsOfKind(info, BagMessageKind::kLaserScan), std::vector<std::string>{"/scan"});
}

TEST_F(RosbagRoundTripTest, ZeroHeaderStampUsesRecordTimeAndUnmountedLaserIsWarned) {
  const auto path = dir_ / "stamps.bag";
  {
    testing::BagTestWriter writer(path);
    writer.WriteOdometry("/odom", MakeOdometry(1.0, 0, 0, 0));
    writer.WriteOdometry("/odom", MakeOdometry(3.0, 2.0, 0, 0));
    BagScan scan = MakeScan(0.0, {1.0f, 2.0f}, "laser");
    scan.record_s = 2.5;
    writer.WriteScan("/scan", scan);
  }
  const Sequence sequence = ReadRosbag(path);
  ASSERT_EQ(sequence.scans.size(), 1u);
  EXPECT_EQ(sequence.scans[0].stamp_s, 2.5);
  EXPECT_NEAR(sequence.odometry.poses()[0].position.x(), 1.5, 1e-12);
  ASSERT_EQ(sequence.warnings.size(), 1u);
  EXPECT_THAT(sequence.warnings[0],
              AllOf(HasSubstr(path.string()), HasSubstr("laser frame 'laser'"), HasSubstr("robot origin")));
}

TEST_F(RosbagRoundTripTest, MountChainFromTfStaticAndOptionsOverride) {
  const auto path = dir_ / "mount.bag";
  {
    testing::BagTestWriter writer(path);
    const double s = std::sqrt(0.5);
    writer.WriteTransforms("/tf_static",
                           {BagStampedPose{0.0, 0.0, "base_link", "plate", BagPose{0.5, 0, 0.3, 0, 0, s, s}},
                            BagStampedPose{0.0, 0.0, "plate", "laser", BagPose{0.1, 0, 0, 0, 0, 0, 1}}});
    writer.WriteOdometry("/odom", MakeOdometry(1.0, 0, 0, 0));
    writer.WriteOdometry("/odom", MakeOdometry(2.0, 0, 0, 0));
    writer.WriteScan("/scan", MakeScan(1.5, {1.0f, 2.0f}, "laser"));
  }
  const Sequence sequence = ReadRosbag(path);
  ASSERT_EQ(sequence.scans.size(), 1u);
  const Pose& mount = sequence.scans[0].sensor_pose_on_robot;
  // plate is turned 90 degrees: 0.1 m along its x is +y on the robot. Heights are dropped (2D).
  EXPECT_NEAR(mount.position.x(), 0.5, 1e-12);
  EXPECT_NEAR(mount.position.y(), 0.1, 1e-12);
  EXPECT_EQ(mount.position.z(), 0.0);
  EXPECT_NEAR(mount.Yaw(), std::acos(0.0), 1e-12);

  BagReadOptions options;
  options.choices.laser_frame = "plate";
  options.name = "renamed";
  const Sequence overridden = ReadRosbag(path, options);
  EXPECT_EQ(overridden.name, "renamed");
  EXPECT_NEAR(overridden.scans[0].sensor_pose_on_robot.position.y(), 0.0, 1e-12);
}

TEST_F(RosbagRoundTripTest, ScansOutsideOdometryAreDroppedAndCounted) {
  const auto path = dir_ / "span.bag";
  {
    testing::BagTestWriter writer(path);
    for (double t : {1.0, 2.0, 3.0, 4.0, 5.0}) writer.WriteScan("/scan", MakeScan(t, {1.0f, 2.0f}));
    writer.WriteOdometry("/odom", MakeOdometry(1.5, 0, 0, 0));
    writer.WriteOdometry("/odom", MakeOdometry(3.5, 0, 0, 0));
  }
  const Sequence sequence = ReadRosbag(path);
  ASSERT_EQ(sequence.scans.size(), 2u);
  EXPECT_EQ(sequence.scans[0].stamp_s, 2.0);
  ASSERT_EQ(sequence.warnings.size(), 1u);
  EXPECT_THAT(sequence.warnings[0], AllOf(HasSubstr("dropped 3 of 5 scans on '/scan'"), HasSubstr("topic '/odom'")));
}

TEST_F(RosbagRoundTripTest, NoScanWithinOdometryIsAnError) {
  const auto path = dir_ / "disjoint.bag";
  {
    testing::BagTestWriter writer(path);
    writer.WriteScan("/scan", MakeScan(1.0, {1.0f, 2.0f}));
    writer.WriteOdometry("/odom", MakeOdometry(10.0, 0, 0, 0));
    writer.WriteOdometry("/odom", MakeOdometry(11.0, 0, 0, 0));
  }
  EXPECT_THAT([&] { ReadRosbag(path); },
              ThrowsMessage<InputError>(
                  AllOf(HasSubstr(path.string()), HasSubstr("none of the 1 scans on '/scan'"), HasSubstr("[10"))));
}

TEST_F(RosbagRoundTripTest, BadQuaternionNamesTopicAndMessage) {
  const auto path = dir_ / "quaternion.bag";
  {
    testing::BagTestWriter writer(path);
    writer.WriteScan("/scan", MakeScan(1.5, {1.0f, 2.0f}));
    writer.WriteOdometry("/odom", MakeOdometry(1.0, 0, 0, 0));
    BagStampedPose broken = MakeOdometry(2.0, 0, 0, 0);
    broken.pose.qw = 0.0;
    writer.WriteOdometry("/odom", broken);
  }
  EXPECT_THAT([&] { ReadRosbag(path); },
              ThrowsMessage<InputError>(
                  AllOf(HasSubstr(path.string()), HasSubstr("topic '/odom' message 1"), HasSubstr("zero norm"))));
}

TEST_F(RosbagRoundTripTest, BagWithoutScansListsItsTopics) {
  const auto path = dir_ / "chatter.bag";
  {
    testing::BagTestWriter writer(path);
    writer.WriteText("/chatter", 1.0, "hi");
  }
  EXPECT_THAT([&] { ReadRosbag(path); },
              ThrowsMessage<InputError>(AllOf(HasSubstr(path.string()), HasSubstr("no sensor_msgs/LaserScan topic"),
                                              HasSubstr("/chatter (std_msgs/String)"))));
}

TEST_F(RosbagRoundTripTest, MissingTruncatedAndForeignFilesAreInputErrors) {
  const auto missing = dir_ / "missing.bag";
  EXPECT_THAT([&] { ReadRos1BagSummary(missing); },
              ThrowsMessage<InputError>(AllOf(HasSubstr(missing.string()), HasSubstr("no such bag file"))));
  const auto text = testing::WriteFile(dir_ / "notes.bag", "this is not a bag\n");
  EXPECT_THAT([&] { ReadRosbag(text); },
              ThrowsMessage<InputError>(AllOf(HasSubstr(text.string()), HasSubstr("not a readable ROS1 bag"))));

  const auto whole = dir_ / "whole.bag";
  {
    testing::BagTestWriter writer(whole);
    for (double t : {1.0, 2.0, 3.0}) writer.WriteScan("/scan", MakeScan(t, std::vector<float>(500, 1.0f)));
  }
  const auto size = std::filesystem::file_size(whole);
  for (const auto keep : {size / 2, size - 10, std::uintmax_t{20}}) {
    const auto cut = dir_ / "cut.bag";
    std::filesystem::copy_file(whole, cut, std::filesystem::copy_options::overwrite_existing);
    std::filesystem::resize_file(cut, keep);
    EXPECT_THROW(ReadRos1BagSummary(cut), InputError) << "kept " << keep << " bytes";
    EXPECT_THROW(ReadRosbag(cut), InputError) << "kept " << keep << " bytes";
  }
}

TEST(BagChoicesTest, ContradictionsNameTheOptions) {
  BagReadOptions both;
  both.choices.reference_topic = "/gt";
  both.choices.reference_frame = "map";
  EXPECT_THAT([&] { CheckBagChoices(both.choices); },
              ThrowsMessage<InputError>(AllOf(HasSubstr("reference_topic"), HasSubstr("reference_frame"))));
  BagReadOptions same;
  same.choices.odometry_topic = same.choices.reference_topic = "/odom";
  EXPECT_THAT([&] { CheckBagChoices(same.choices); }, ThrowsMessage<InputError>(HasSubstr("odometry_topic")));
  BagReadOptions no_base;
  no_base.choices.base_frame = "/";
  EXPECT_THAT([&] { CheckBagChoices(no_base.choices); }, ThrowsMessage<InputError>(HasSubstr("base_frame")));
  EXPECT_NO_THROW(CheckBagChoices(BagChoices{}));
}

}  // namespace
}  // namespace slamsweep::evaluator
