// The two real ROS 2 bags of ../shared/datasets/ros2 (PROVENANCE.txt there), read by slamsweep and, for the
// MCAP one, by foxglove's npm reader (@mcap/core with @foxglove/rosmsg2-serialization): the same topics,
// counts and poses, message by message.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/bag/bag_messages.h"
#include "evaluator/formats/rosbag2/rosbag2_reader.h"
#include "tests/evaluator/formats/rosbag2/bag_fixtures.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

constexpr const char* kNav2 = "datasets/ros2/evo-nav2-turtlebot/nav2_turtlebot.mcap";
constexpr const char* kTfExample = "datasets/ros2/evo-tf-example";

std::map<std::string, std::pair<std::string, std::size_t>> TopicsOf(const BagSummary& summary) {
  std::map<std::string, std::pair<std::string, std::size_t>> topics;
  for (const BagTopic& topic : summary.topics) topics[topic.topic] = {topic.datatype, topic.message_count};
  return topics;
}

TEST(SharedRos2BagsTest, Nav2McapHasTheTopicsAndCountsOfItsProvenance) {
  SLAMSWEEP_REQUIRE_SHARED(bag, kNav2);
  const Rosbag2Bag ours(bag);
  // Counted by an independent MCAP walker (PROVENANCE.txt).
  const std::map<std::string, std::pair<std::string, std::size_t>> expected = {
      {"/amcl_pose", {"geometry_msgs/msg/PoseWithCovarianceStamped", 135}},
      {"/odom", {"nav_msgs/msg/Odometry", 2639}},
      {"/tf", {"tf2_msgs/msg/TFMessage", 5422}},
      {"/tf_static", {"tf2_msgs/msg/TFMessage", 1}}};
  EXPECT_EQ(TopicsOf(ours.Summary()), expected);
  EXPECT_TRUE(ours.Summary().notes.empty());
  // Log times are wall time (~1.778e9 s), header stamps simulation time.
  EXPECT_GT(ours.Summary().start_s, 1.7e9);
}

TEST(SharedRos2BagsTest, Nav2PosesAreTheOnesTheNpmReaderDecodes) {
  SLAMSWEEP_REQUIRE_SHARED(bag, kNav2);
  REQUIRE_NPM_TOOLS();
  const nlohmann::json npm = testing::NpmDump(bag, "/odom /amcl_pose /tf_static");
  EXPECT_EQ(npm.at("profile"), "ros2");
  const Rosbag2Bag ours(bag);
  for (const nlohmann::json& topic : npm.at("topics")) {
    const auto found = TopicsOf(ours.Summary()).at(topic.at("topic").get<std::string>());
    EXPECT_EQ(found.first, topic.at("type").get<std::string>());
    EXPECT_EQ(found.second, topic.at("count").get<std::size_t>());
  }
  BagRequest request;
  request.pose_topics = {"/odom", "/amcl_pose"};
  request.read_tf = true;
  const BagMessages messages = ours.ReadMessages(request);
  for (const std::string topic : {"/odom", "/amcl_pose"}) {
    const nlohmann::json& expected = npm.at("messages").at(topic);
    const std::vector<BagStampedPose>& actual = messages.poses.at(topic);
    ASSERT_EQ(actual.size(), expected.size()) << topic;
    for (std::size_t i = 0; i < actual.size(); ++i) {
      const nlohmann::json& message = expected[i];
      ASSERT_EQ(actual[i].stamp_s,
                RosTimeSeconds(message.at("stamp")[0].get<std::int64_t>(), message.at("stamp")[1].get<std::uint32_t>()))
          << topic << " " << i;
      ASSERT_EQ(actual[i].record_s, std::stod(message.at("log_time").get<std::string>()) / 1e9) << topic << " " << i;
      ASSERT_EQ(actual[i].frame_id, message.at("frame_id").get<std::string>());
      const BagPose& pose = actual[i].pose;
      const std::vector<double> components = {pose.x_m, pose.y_m, pose.z_m, pose.qx, pose.qy, pose.qz, pose.qw};
      ASSERT_EQ(components, message.at("pose").get<std::vector<double>>()) << topic << " " << i;
    }
  }
  // The first and last poses as the npm reader gives them, for the record.
  EXPECT_EQ(npm.at("messages").at("/amcl_pose")[0].at("stamp"), nlohmann::json::parse("[924, 102000000]"));
  EXPECT_EQ(npm.at("messages").at("/amcl_pose")[134].at("stamp"), nlohmann::json::parse("[1023, 300000000]"));
  EXPECT_DOUBLE_EQ(messages.poses.at("/amcl_pose").front().pose.x_m, 4.36519665396771);
  EXPECT_DOUBLE_EQ(messages.poses.at("/amcl_pose").back().pose.y_m, 7.787517263356672);
  ASSERT_EQ(npm.at("messages").at("/tf_static").size(), 1u);
  EXPECT_EQ(messages.tf_static.size(), npm.at("messages").at("/tf_static")[0].at("transforms").size());
  EXPECT_EQ(messages.tf_static.size(), 29u);
}

TEST(SharedRos2BagsTest, Nav2TrajectoriesFromTopicsAndTf) {
  SLAMSWEEP_REQUIRE_SHARED(bag, kNav2);
  std::vector<std::string> warnings;
  const Trajectory odom = ReadRosbag2Trajectory(bag, "/odom", warnings);
  EXPECT_EQ(odom.size(), 2639u);
  const Trajectory amcl = ReadRosbag2Trajectory(bag, "/amcl_pose", warnings);
  EXPECT_EQ(amcl.size(), 135u);
  EXPECT_DOUBLE_EQ(amcl.StartS(), 924.102);
  // The robot's odometry in /tf (evo's /tf:PARENT.CHILD), at every stamp of its transforms.
  const Trajectory tf = ReadRosbag2Trajectory(bag, "/tf:odom.base_footprint", warnings);
  EXPECT_GT(tf.size(), 100u);
  EXPECT_THAT([&] { ReadRosbag2Trajectory(bag, "/tf:odom.no_such_frame", warnings); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("frames in the bag:")));
  EXPECT_THAT([&] { ReadRosbag2Trajectory(bag, "/no_topic", warnings); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("no trajectory topic '/no_topic'")));
}

TEST(SharedRos2BagsTest, TfExampleFolderAndItsDb3) {
  SLAMSWEEP_REQUIRE_SHARED(folder, kTfExample);
  const std::map<std::string, std::pair<std::string, std::size_t>> expected = {
      {"/tf", {"tf2_msgs/msg/TFMessage", 517}}, {"/tf_static", {"tf2_msgs/msg/TFMessage", 1}}};
  const Rosbag2Bag bag_folder(folder);
  EXPECT_EQ(TopicsOf(bag_folder.Summary()), expected);
  EXPECT_EQ(bag_folder.Name(), "evo-tf-example");
  const Rosbag2Bag lone_file(folder / "tf_example.db3");
  EXPECT_EQ(TopicsOf(lone_file.Summary()), expected);
  EXPECT_EQ(lone_file.Name(), "tf_example");
  BagRequest request;
  request.read_tf = true;
  const BagMessages messages = bag_folder.ReadMessages(request);
  EXPECT_EQ(messages.tf_static.front().frame_id, "base_footprint");
  EXPECT_EQ(messages.tf_static.front().child_frame_id, "base_link");
  EXPECT_EQ(messages.tf.front().frame_id, "odom");
  EXPECT_EQ(messages.tf.front().child_frame_id, "base_footprint");
  std::vector<std::string> warnings;
  EXPECT_EQ(ReadRosbag2Trajectory(folder, "/tf:odom.base_link", warnings).size(), 517u);
  // No scan topic: as a sequence, an error listing what the bag holds.
  EXPECT_THAT([&] { ReadRosbag2(folder); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr("no sensor_msgs/LaserScan topic; topics in the bag: /tf (tf2_msgs/msg/TFMessage)")));
}

}  // namespace
}  // namespace slamsweep::evaluator
