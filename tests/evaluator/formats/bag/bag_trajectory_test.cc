// Trajectories named in a bag evo's way, on messages made by hand: arguments split at the right ':',
// tf pairs whose frame names hold dots, and the errors.
#include "evaluator/formats/bag/bag_trajectory.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "evaluator/core/input_error.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

BagStampedPose Transform(double stamp_s, const std::string& parent, const std::string& child, double x_m) {
  return BagStampedPose{stamp_s, stamp_s, parent, child, BagPose{x_m, 0, 0, 0, 0, 0, 1}};
}

/// A bag with /odom (Odometry, 3 poses, one repeated stamp), /scan, and /tf: map -> odom.main fixed,
/// odom.main -> base.link moving; and "a" -> "b.c" beside "a.b" -> "c" to make a split ambiguous.
class BagTrajectoryTest : public ::testing::Test {
 protected:
  BagTrajectoryTest() {
    summary_.topics = {{"/odom", "nav_msgs/msg/Odometry", 3},
                       {"/scan", "sensor_msgs/msg/LaserScan", 1},
                       {"/tf", "tf2_msgs/msg/TFMessage", 4}};
    messages_.poses["/odom"] = {Transform(1.0, "odom", "base", 0.0), Transform(2.0, "odom", "base", 1.0),
                                Transform(2.0, "odom", "base", 5.0)};
    messages_.tf = {Transform(1.0, "map", "odom.main", 10.0),
                    Transform(1.0, "odom.main", "base.link", 0.0),
                    Transform(2.0, "odom.main", "base.link", 2.0),
                    Transform(2.0, "map", "odom.main", 10.0),
                    Transform(1.0, "a", "b.c", 1.0),
                    Transform(2.0, "a", "b.c", 1.0),
                    Transform(1.0, "a.b", "c", 1.0),
                    Transform(2.0, "a.b", "c", 1.0)};
  }

  Trajectory Read(std::string_view selector) {
    const BagMessageSource read = [&](const BagRequest& request) {
      requests_.push_back(request);
      BagMessages out;
      for (const std::string& topic : request.pose_topics) out.poses[topic] = messages_.poses.at(topic);
      if (request.read_tf) out.tf = messages_.tf;
      return out;
    };
    return ReadBagTrajectory("run.mcap", summary_, read, selector, warnings_);
  }

  BagSummary summary_;
  BagMessages messages_;
  std::vector<BagRequest> requests_;
  std::vector<std::string> warnings_;
};

TEST_F(BagTrajectoryTest, ATopicsPosesByStampWithARepeatDropped) {
  const Trajectory odom = Read("/odom");
  ASSERT_EQ(odom.size(), 2u);
  EXPECT_EQ(odom.poses()[1].position.x(), 1.0);
  ASSERT_EQ(requests_.size(), 1u);
  EXPECT_EQ(requests_[0].pose_topics, std::vector<std::string>{"/odom"});
  EXPECT_FALSE(requests_[0].read_tf);
  ASSERT_EQ(warnings_.size(), 1u);
  EXPECT_THAT(warnings_[0], HasSubstr("dropped 1 message(s) on '/odom' repeating a stamp"));
}

TEST_F(BagTrajectoryTest, ATfPairWithDotsInItsFramesSplitsWhereTheTreeJoinsThem) {
  // "map.odom.main" could be map | odom.main or map.odom | main: only the first names two joined frames.
  const Trajectory track = Read("/tf:map.base.link");
  ASSERT_EQ(track.size(), 2u);
  EXPECT_EQ(track.poses()[1].position.x(), 12.0);
  EXPECT_EQ(Read("/tf:odom.main.base.link").poses()[1].position.x(), 2.0);
}

TEST_F(BagTrajectoryTest, ErrorsNameTheBagTheSelectorAndTheCandidates) {
  EXPECT_THAT([&] { Read(""); }, ThrowsMessage<InputError>(AllOf(HasSubstr("run.mcap: a bag holds many trajectories"),
                                                                 HasSubstr("run.mcap:/tf:PARENT.CHILD"))));
  EXPECT_THAT([&] { Read("/scan"); },
              ThrowsMessage<InputError>(HasSubstr("trajectory topic '/scan' holds sensor_msgs/msg/LaserScan, expected "
                                                  "nav_msgs/msg/Odometry, geometry_msgs/msg/PoseStamped, "
                                                  "geometry_msgs/msg/PoseWithCovarianceStamped or "
                                                  "geometry_msgs/msg/TransformStamped")));
  EXPECT_THAT([&] { Read("/gone"); }, ThrowsMessage<InputError>(HasSubstr("no trajectory topic '/gone'; topics in the "
                                                                          "bag: /odom (nav_msgs/msg/Odometry)")));
  EXPECT_THAT([&] { Read("/tf:map.nowhere"); },
              ThrowsMessage<InputError>(HasSubstr("frames in the bag: a, a.b, b.c, base.link, c, map, odom.main")));
  EXPECT_THAT([&] { Read("/tf:a.b.c"); },
              ThrowsMessage<InputError>(AllOf(HasSubstr("splits into frames in more than one way"),
                                              HasSubstr("'a' -> 'b.c'"), HasSubstr("'a.b' -> 'c'"))));
}

TEST(SplitBagTrajectoryArgumentTest, AnExistingNameWinsThenTheLongestExistingPrefix) {
  testing::TempDir dir;
  const std::filesystem::path bag = testing::WriteFile(dir / "run.mcap", "");
  const std::filesystem::path odd = testing::WriteFile(dir / "odd:name.mcap", "");
  const auto whole = SplitBagTrajectoryArgument(odd.string());
  ASSERT_TRUE(whole);
  EXPECT_EQ(whole->bag, odd);
  EXPECT_EQ(whole->selector, "");
  const auto tf = SplitBagTrajectoryArgument(bag.string() + ":/tf:map.base_link");
  ASSERT_TRUE(tf);
  EXPECT_EQ(tf->bag, bag);
  EXPECT_EQ(tf->selector, "/tf:map.base_link");
  const auto topic = SplitBagTrajectoryArgument(odd.string() + ":/odom");
  ASSERT_TRUE(topic);
  EXPECT_EQ(topic->bag, odd);
  EXPECT_EQ(topic->selector, "/odom");
  EXPECT_FALSE(SplitBagTrajectoryArgument((dir / "none.mcap:/odom").string()));
}

}  // namespace
}  // namespace slamsweep::evaluator
