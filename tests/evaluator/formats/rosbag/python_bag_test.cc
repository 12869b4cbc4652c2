// Bags written by an independent writer, Debian's python3-rosbag (make_test_bags.py), read back.
// Every expected value is computed by hand from the values in make_test_bags.py.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <numbers>
#include <optional>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/bag/bag_sequence.h"
#include "evaluator/formats/bag/bag_topics.h"
#include "evaluator/formats/rosbag/ros1_bag_io.h"
#include "evaluator/formats/rosbag/rosbag_reader.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

/// The bags, written once for all tests; or why they could not be.
struct PythonBags {
  testing::TempDir dir;
  /// Why the bags cannot be written here (no python3-rosbag): a skip, or a failure under CI.
  std::string unavailable;
  /// The writer script itself failed: always a failure.
  std::string failed;
};

/// Runs `command` with its output in `log`; returns that output when it fails, empty on success.
std::optional<std::string> RunLogged(const std::string& command, const std::filesystem::path& log) {
  if (std::system((command + " > '" + log.string() + "' 2>&1").c_str()) == 0) return std::nullopt;
  std::ifstream in(log);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void MakeBags(PythonBags& bags) {
  const std::string python = SLAMSWEEP_SYSTEM_PYTHON;
  const std::filesystem::path log = bags.dir / "python.log";
  const std::string imports = "import rosbag, genpy, sensor_msgs.msg, nav_msgs.msg, tf2_msgs.msg";
  if (!std::filesystem::exists(python) || RunLogged(python + " -c '" + imports + "'", log)) {
    bags.unavailable = python +
                       " with the rosbag module is not available (Debian: python3-rosbag python3-sensor-msgs "
                       "python3-nav-msgs python3-tf2-msgs; scripts/install-deps.sh)";
    return;
  }
  const std::string script = SLAMSWEEP_ROSBAG_TEST_SCRIPT;
  if (const auto output = RunLogged(python + " '" + script + "' '" + bags.dir.path().string() + "'", log)) {
    bags.failed = script + " failed:\n" + *output;
  }
}

const PythonBags& Bags() {
  static PythonBags bags;
  static const bool made = (MakeBags(bags), true);
  (void)made;
  return bags;
}

// Skips (fails under CI=true) when python3-rosbag is missing; otherwise `var` is the bag's path.
#define REQUIRE_PYTHON_BAG(var, name)                                      \
  if (!Bags().failed.empty()) FAIL() << Bags().failed;                     \
  if (!Bags().unavailable.empty()) {                                       \
    if (::slamsweep::testing::RunningInCi()) FAIL() << Bags().unavailable; \
    GTEST_SKIP() << Bags().unavailable;                                    \
  }                                                                        \
  const std::filesystem::path var = Bags().dir / (name)

void ExpectPlanar(const Pose& pose, double x_m, double y_m, double yaw_rad) {
  EXPECT_NEAR(pose.position.x(), x_m, 1e-12);
  EXPECT_NEAR(pose.position.y(), y_m, 1e-12);
  EXPECT_NEAR(NormalizeAngleRad(pose.Yaw() - yaw_rad), 0.0, 1e-12);
}

BagReadOptions WithReferenceTopic(const std::string& topic) {
  BagReadOptions options;
  options.choices.reference_topic = topic;
  return options;
}

TEST(PythonBagTest, InspectListsTopics) {
  REQUIRE_PYTHON_BAG(bag, "basic.bag");
  const BagSummary info = ReadRos1BagSummary(bag);
  ASSERT_EQ(info.topics.size(), 4u);
  EXPECT_EQ(info.topics[0].topic, "/ground_truth");
  EXPECT_EQ(info.topics[0].message_count, 5u);
  EXPECT_EQ(info.topics[1].topic, "/odom");
  EXPECT_EQ(info.topics[1].message_count, 3u);
  EXPECT_EQ(info.topics[2].topic, "/scan");
  EXPECT_EQ(info.topics[2].datatype, "sensor_msgs/LaserScan");
  EXPECT_EQ(info.topics[2].message_count, 7u);
  EXPECT_EQ(info.topics[3].topic, "/tf_static");
  EXPECT_EQ(info.topics[3].datatype, "tf2_msgs/TFMessage");
  EXPECT_EQ(info.message_count, 16u);
  EXPECT_EQ(info.start_s, 99.0);
  EXPECT_EQ(info.end_s, 102.5);
}

TEST(PythonBagTest, TwoOdometryTopicsAreAmbiguousUntilOneIsTheReference) {
  REQUIRE_PYTHON_BAG(bag, "basic.bag");
  EXPECT_THAT([&] { ReadRosbag(bag); },
              ThrowsMessage<InputError>(AllOf(HasSubstr(bag.string()), HasSubstr("2 nav_msgs/Odometry topics"),
                                              HasSubstr("/ground_truth, /odom"), HasSubstr("odometry_topic"))));
}

TEST(PythonBagTest, ScansOdometryMountAndReference) {
  REQUIRE_PYTHON_BAG(bag, "basic.bag");
  const Sequence sequence = ReadRosbag(bag, WithReferenceTopic("/ground_truth"));
  EXPECT_EQ(sequence.name, "basic");
  // Of stamps 99.5 100 100.5 100.5 101.25 102 102.5: one repeat, two outside odometry [100, 102].
  ASSERT_EQ(sequence.scans.size(), 4u);
  const double stamps[] = {100.0, 100.5, 101.25, 102.0};
  for (std::size_t i = 0; i < 4; ++i) {
    const LaserScan& scan = sequence.scans[i];
    EXPECT_EQ(scan.stamp_s, stamps[i]);
    EXPECT_EQ(sequence.odometry.stamps_s()[i], stamps[i]);
    EXPECT_EQ(scan.angle_min_rad, -1.5);
    EXPECT_EQ(scan.angle_increment_rad, 0.75);
    EXPECT_EQ(scan.range_min_m, static_cast<double>(0.1f));
    EXPECT_EQ(scan.range_max_m, 30.0);
    // nan, inf and -inf are "no return", stored as range_max.
    EXPECT_EQ(scan.ranges_m, (std::vector<float>{1.0f, 30.0f, 30.0f, 30.0f, 2.5f}));
    ExpectPlanar(scan.sensor_pose_on_robot, 0.2, 0.1, std::numbers::pi / 2);
  }
  // Odometry (100: 0 0 0) (101: 1 2 0.5) (102: 2 2 1) interpolated at the scan stamps.
  ExpectPlanar(sequence.odometry.poses()[0], 0.0, 0.0, 0.0);
  ExpectPlanar(sequence.odometry.poses()[1], 0.5, 1.0, 0.25);
  ExpectPlanar(sequence.odometry.poses()[2], 1.25, 2.0, 0.625);
  ExpectPlanar(sequence.odometry.poses()[3], 2.0, 2.0, 1.0);

  ASSERT_TRUE(sequence.reference.has_value());
  ASSERT_EQ(sequence.reference->size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) {
    const double step = 0.5 * static_cast<double>(k);
    EXPECT_EQ(sequence.reference->stamps_s()[k], 100.0 + step);
    ExpectPlanar(sequence.reference->poses()[k], step, -step, 0.0);
  }
  ASSERT_EQ(sequence.warnings.size(), 2u);
  EXPECT_THAT(sequence.warnings[0], HasSubstr("dropped 1 scan(s) on '/scan' repeating a stamp"));
  EXPECT_THAT(sequence.warnings[1], AllOf(HasSubstr(bag.string()), HasSubstr("dropped 2 of 7 scans on '/scan'")));
}

TEST(PythonBagTest, OdometryAndReferenceFromOldStyleTf) {
  REQUIRE_PYTHON_BAG(bag, "tf_odometry.bag");
  BagReadOptions options;
  options.choices.reference_frame = "map";
  const Sequence sequence = ReadRosbag(bag, options);
  EXPECT_TRUE(sequence.warnings.empty()) << sequence.warnings.front();
  ASSERT_EQ(sequence.scans.size(), 2u);
  // odom -> base_link (10: 0 0 0) (11: 1 0 pi/2) (12: 1 1 pi/2) at 10.5 and 11.5.
  ExpectPlanar(sequence.odometry.poses()[0], 0.5, 0.0, std::numbers::pi / 4);
  ExpectPlanar(sequence.odometry.poses()[1], 1.0, 0.5, std::numbers::pi / 2);
  // base_link -> /base_laser was sent once, at 10 s, on /tf: taken as the mount.
  ExpectPlanar(sequence.scans[0].sensor_pose_on_robot, 0.3, 0.0, std::numbers::pi);
  ExpectPlanar(sequence.scans[1].sensor_pose_on_robot, 0.3, 0.0, std::numbers::pi);
  // map -> odom is (1, 0, pi/2) throughout; map -> base_link at 10, 11, 12 s.
  ASSERT_TRUE(sequence.reference.has_value());
  EXPECT_EQ(sequence.reference->stamps_s(), (std::vector<double>{10.0, 11.0, 12.0}));
  ExpectPlanar(sequence.reference->poses()[0], 1.0, 0.0, std::numbers::pi / 2);
  ExpectPlanar(sequence.reference->poses()[1], 1.0, 1.0, std::numbers::pi);
  ExpectPlanar(sequence.reference->poses()[2], 0.0, 1.0, std::numbers::pi);
}

TEST(PythonBagTest, MissingReferenceFrameIsAnError) {
  REQUIRE_PYTHON_BAG(bag, "tf_odometry.bag");
  BagReadOptions options;
  options.choices.reference_frame = "world";
  EXPECT_THAT([&] { ReadRosbag(bag, options); },
              ThrowsMessage<InputError>(AllOf(HasSubstr(bag.string()), HasSubstr("reference_frame 'world'"))));
}

TEST(PythonBagTest, AmbiguousScanTopicsAreListed) {
  REQUIRE_PYTHON_BAG(bag, "two_of_each.bag");
  EXPECT_THAT([&] { ReadRosbag(bag); },
              ThrowsMessage<InputError>(AllOf(HasSubstr(bag.string()), HasSubstr("2 sensor_msgs/LaserScan topics"),
                                              HasSubstr("/scan_front, /scan_rear"), HasSubstr("scan_topic"))));
  BagReadOptions options;
  options.choices.scan_topic = "/scan_front";
  EXPECT_THAT([&] { ReadRosbag(bag, options); },
              ThrowsMessage<InputError>(AllOf(HasSubstr("2 nav_msgs/Odometry topics"), HasSubstr("/odom_a, /odom_b"))));
}

TEST(PythonBagTest, ChosenTopicsAreRead) {
  REQUIRE_PYTHON_BAG(bag, "two_of_each.bag");
  BagReadOptions options = WithReferenceTopic("/odom_b");
  options.choices.scan_topic = "/scan_rear";
  const Sequence sequence = ReadRosbag(bag, options);
  ASSERT_EQ(sequence.scans.size(), 2u);
  EXPECT_EQ(sequence.scans[0].ranges_m, std::vector<float>(5, 2.0f));
  ExpectPlanar(sequence.odometry.poses()[0], 1.5, 0.0, 0.0);  // /odom_a: (t, 0)
  ExpectPlanar(sequence.odometry.poses()[1], 2.5, 0.0, 0.0);
  ASSERT_TRUE(sequence.reference.has_value());
  ExpectPlanar(sequence.reference->poses()[2], 0.0, 3.0, 0.0);  // /odom_b: (0, t)
}

TEST(PythonBagTest, WrongTypeAndMissingTopicsNameTheTopic) {
  REQUIRE_PYTHON_BAG(bag, "two_of_each.bag");
  BagReadOptions scan_is_odometry;
  scan_is_odometry.choices.scan_topic = "/odom_a";
  scan_is_odometry.choices.odometry_topic = "/odom_b";
  EXPECT_THAT([&] { ReadRosbag(bag, scan_is_odometry); },
              ThrowsMessage<InputError>(
                  AllOf(HasSubstr(bag.string()), HasSubstr("scan topic '/odom_a' holds nav_msgs/Odometry, expected "
                                                           "sensor_msgs/LaserScan"))));
  BagReadOptions odometry_is_scan;
  odometry_is_scan.choices.scan_topic = "/scan_front";
  odometry_is_scan.choices.odometry_topic = "/scan_rear";
  EXPECT_THAT([&] { ReadRosbag(bag, odometry_is_scan); },
              ThrowsMessage<InputError>(HasSubstr("odometry topic '/scan_rear' holds sensor_msgs/LaserScan")));
  BagReadOptions missing;
  missing.choices.scan_topic = "/nope";
  missing.choices.odometry_topic = "/odom_a";
  EXPECT_THAT([&] { ReadRosbag(bag, missing); },
              ThrowsMessage<InputError>(
                  AllOf(HasSubstr("no scan topic '/nope'"), HasSubstr("/scan_front (sensor_msgs/LaserScan)"))));
  BagReadOptions missing_reference = WithReferenceTopic("/gt");
  missing_reference.choices.scan_topic = "/scan_front";
  missing_reference.choices.odometry_topic = "/odom_a";
  EXPECT_THAT([&] { ReadRosbag(bag, missing_reference); },
              ThrowsMessage<InputError>(HasSubstr("no reference topic '/gt'")));
}

TEST(PythonBagTest, AReferenceFromPoseStampedOrPoseWithCovarianceStamped) {
  REQUIRE_PYTHON_BAG(bag, "pose_references.bag");
  const Sequence pose = ReadRosbag(bag, WithReferenceTopic("/pose_gt"));
  ASSERT_TRUE(pose.reference.has_value());
  ASSERT_EQ(pose.reference->size(), 2u);
  EXPECT_EQ(pose.reference->stamps_s()[1], 3.0);
  ExpectPlanar(pose.reference->poses()[0], 5.0, 1.0, 0.5);
  ExpectPlanar(pose.reference->poses()[1], 6.0, 2.0, 1.0);
  const Sequence amcl = ReadRosbag(bag, WithReferenceTopic("/amcl"));
  ASSERT_TRUE(amcl.reference.has_value());
  ExpectPlanar(amcl.reference->poses()[1], -6.0, -2.0, -1.0);
  // The same topics as trajectories, evo's way (BAG:TOPIC).
  std::vector<std::string> warnings;
  EXPECT_EQ(ReadRosbagTrajectory(bag, "/amcl", warnings).size(), 2u);
  EXPECT_EQ(ReadRosbagTrajectory(bag, "/odom", warnings).size(), 3u);
  EXPECT_TRUE(warnings.empty());
  EXPECT_THAT([&] { ReadRosbag(bag, WithReferenceTopic("/scan")); },
              ThrowsMessage<InputError>(
                  HasSubstr("reference topic '/scan' holds sensor_msgs/LaserScan, expected nav_msgs/Odometry, "
                            "geometry_msgs/PoseStamped or geometry_msgs/PoseWithCovarianceStamped")));
  EXPECT_THAT([&] { ReadRosbagTrajectory(bag, "/scan", warnings); },
              ThrowsMessage<InputError>(HasSubstr("trajectory topic '/scan' holds sensor_msgs/LaserScan")));
}

TEST(PythonBagTest, NoOdometryAtAllIsAnError) {
  REQUIRE_PYTHON_BAG(bag, "scans_only.bag");
  EXPECT_THAT([&] { ReadRosbag(bag); },
              ThrowsMessage<InputError>(AllOf(HasSubstr(bag.string()), HasSubstr("no nav_msgs/Odometry topic"),
                                              HasSubstr("/tf from 'odom' to 'base_link'"))));
}

}  // namespace
}  // namespace slamsweep::evaluator
