// The command line on ROS 2 bags: trajectories named evo's way in `eval` and `data convert --to tum`, a
// sequence written as a bag and read back by `data info`, and the errors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "evaluator/formats/trajectory/tum_format.h"
#include "tests/cli/run_cli.h"
#include "tests/support/shared_data.h"

namespace slamsweep {
namespace {

using ::testing::HasSubstr;
using testing::RunCli;

constexpr const char* kNav2 = "datasets/ros2/evo-nav2-turtlebot/nav2_turtlebot.mcap";

TEST(Ros2BagEvalTest, ApeOfOdometryAgainstAmclPairsAsTheStampsAllow) {
  SLAMSWEEP_REQUIRE_SHARED(bag, kNav2);
  const std::string odom = bag.string() + ":/odom";
  const std::string amcl = bag.string() + ":/amcl_pose";
  // /odom runs at 27.8 Hz (a pose every 36 ms); 134 of the 135 /amcl_pose stamps lie within 18 ms of one.
  const auto close = RunCli({"eval", "ape", odom, amcl, "--align", "se2", "--t-max-diff", "0.02", "--json"});
  ASSERT_EQ(close.exit_code, 0) << close.err;
  const nlohmann::json result = nlohmann::json::parse(close.out);
  EXPECT_EQ(result.at("pairs"), 134);
  EXPECT_EQ(result.at("estimate_unpaired"), 1);
  // The first /amcl_pose (924.102 s) comes 4.698 s before the first /odom (928.800 s): only a window that
  // wide pairs all 135.
  const auto all = RunCli({"eval", "ape", odom, amcl, "--align", "se2", "--t-max-diff", "4.7", "--json"});
  ASSERT_EQ(all.exit_code, 0) << all.err;
  EXPECT_EQ(nlohmann::json::parse(all.out).at("pairs"), 135);
  // --ref-format bag says so explicitly; a tf pair names the same odometry through /tf.
  const auto explicit_format = RunCli({"eval", "ape", odom, amcl, "--ref-format", "bag", "--est-format", "bag",
                                       "--align", "se2", "--t-max-diff", "0.02", "--json"});
  ASSERT_EQ(explicit_format.exit_code, 0) << explicit_format.err;
  EXPECT_EQ(nlohmann::json::parse(explicit_format.out).at("pairs"), 134);
  const auto tf = RunCli({"eval", "ape", bag.string() + ":/tf:odom.base_footprint", amcl, "--align", "se2",
                          "--t-max-diff", "0.02", "--json"});
  ASSERT_EQ(tf.exit_code, 0) << tf.err;
  EXPECT_GT(nlohmann::json::parse(tf.out).at("pairs").get<int>(), 100);
}

TEST(Ros2BagEvalTest, ABagWithoutATopicOrAWrongTopicExitsTwoNamingIt) {
  SLAMSWEEP_REQUIRE_SHARED(bag, kNav2);
  const auto alone = RunCli({"eval", "ape", bag.string(), bag.string() + ":/amcl_pose"});
  EXPECT_EQ(alone.exit_code, 2);
  EXPECT_THAT(alone.err, HasSubstr("a bag holds many trajectories: name one as"));
  const auto wrong = RunCli({"eval", "ape", bag.string() + ":/tf", bag.string() + ":/amcl_pose"});
  EXPECT_EQ(wrong.exit_code, 2);
  EXPECT_THAT(wrong.err, HasSubstr("trajectory topic '/tf' holds tf2_msgs/msg/TFMessage, expected"));
  const auto missing =
      RunCli({"eval", "rpe", "/no/such.mcap:/odom", bag.string() + ":/amcl_pose", "--delta", "1", "--delta-unit", "f"});
  EXPECT_EQ(missing.exit_code, 2);
}

TEST(Ros2BagConvertTest, ATopicBecomesATumTrajectory) {
  SLAMSWEEP_REQUIRE_SHARED(bag, kNav2);
  testing::TempDir dir;
  const auto run =
      RunCli({"data", "convert", bag.string() + ":/amcl_pose", "--to", "tum", "-o", (dir / "amcl.tum").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const evaluator::Trajectory amcl = evaluator::ReadTum(dir / "amcl.tum");
  ASSERT_EQ(amcl.size(), 135u);
  EXPECT_DOUBLE_EQ(amcl.StartS(), 924.102);
  EXPECT_DOUBLE_EQ(amcl.poses().front().position.x(), 4.36519665396771);
  const auto not_tum =
      RunCli({"data", "convert", bag.string() + ":/amcl_pose", "--to", "carmen", "-o", (dir / "x.log").string()});
  EXPECT_EQ(not_tum.exit_code, 2);
  EXPECT_THAT(not_tum.err, HasSubstr("converts --to tum only"));
}

TEST(Ros2BagConvertTest, IntelAsBagsOfBothStoragesReadsBackWithItsReference) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  testing::TempDir dir;
  const auto source = RunCli({"data", "info", "intel", "--json"});
  ASSERT_EQ(source.exit_code, 0) << source.err;
  const nlohmann::json expected = nlohmann::json::parse(source.out);
  for (const std::string storage : {"mcap", "sqlite3"}) {
    const std::string folder = (dir / ("intel_" + storage)).string();
    const auto convert = RunCli({"data", "convert", "intel", "--to", "rosbag2", "--storage", storage, "-o", folder});
    ASSERT_EQ(convert.exit_code, 0) << convert.err;
    EXPECT_THAT(convert.out, HasSubstr("(910 scans, reference as /ground_truth)"));
    const auto two_odometries = RunCli({"data", "info", folder});
    EXPECT_EQ(two_odometries.exit_code, 2);
    EXPECT_THAT(two_odometries.err, HasSubstr("2 nav_msgs/Odometry topics (/ground_truth, /odom)"));
    const auto info = RunCli({"data", "info", folder, "--reference-topic", "/ground_truth", "--json"});
    ASSERT_EQ(info.exit_code, 0) << info.err;
    const nlohmann::json read = nlohmann::json::parse(info.out);
    EXPECT_EQ(read.at("scans"), expected.at("scans"));
    EXPECT_EQ(read.at("beams"), expected.at("beams"));
    EXPECT_EQ(read.at("has_reference"), true);
    EXPECT_EQ(read.at("recorded_odometry"), true);
    EXPECT_NEAR(read.at("duration_s").get<double>(), expected.at("duration_s").get<double>(), 1e-6);
    // The same odometry through /tf.
    const auto by_tf =
        RunCli({"data", "info", folder, "--odometry-topic", "/odom", "--reference-frame", "map", "--json"});
    EXPECT_EQ(by_tf.exit_code, 2);  // /ground_truth is a topic, not a /tf frame
    EXPECT_THAT(by_tf.err, HasSubstr("no time-varying /tf from reference_frame 'map' to 'base_link'"));
  }
  const auto exists = RunCli({"data", "convert", "intel", "--to", "rosbag2", "-o", (dir / "intel_mcap").string()});
  EXPECT_EQ(exists.exit_code, 2);
  EXPECT_THAT(exists.err, HasSubstr("exists and is not empty"));
}

TEST(Ros2BagConvertTest, AFolderWithoutMetadataExitsTwoNamingIt) {
  testing::TempDir dir;
  std::filesystem::create_directories(dir / "not_a_bag");
  const auto info = RunCli({"data", "info", (dir / "not_a_bag").string()});
  EXPECT_EQ(info.exit_code, 2);
  EXPECT_THAT(info.err, HasSubstr("no metadata.yaml in the folder"));
}

}  // namespace
}  // namespace slamsweep
