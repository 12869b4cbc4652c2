// A bag's messages made by hand become a sequence: the odometry stream as the recorded readings, and a
// warning when header stamps are not the bag's record times.
#include "evaluator/formats/bag/bag_sequence.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

BagScan Scan(double stamp_s, double record_s) {
  BagScan scan;
  scan.stamp_s = stamp_s;
  scan.record_s = record_s;
  scan.frame_id = "base_link";
  scan.angle_min_rad = -1.0f;
  scan.angle_increment_rad = 0.5f;
  scan.range_max_m = 10.0f;
  scan.ranges_m = {1.0f, 2.0f, 3.0f, 4.0f, 5.0f};
  return scan;
}

Sequence ReadMessages(const BagMessages& messages) {
  BagSummary summary;
  summary.topics = {{"/odom", "nav_msgs/msg/Odometry", messages.poses.at("/odom").size()},
                    {"/scan", "sensor_msgs/msg/LaserScan", messages.scans.size()}};
  BagReadOptions options;
  options.name = "hand";
  return ReadBagSequence(
      "hand.mcap", summary, [&](const BagRequest&) { return messages; }, options);
}

TEST(BagSequenceTest, AnOdometryStreamDenserThanTheScansIsTheRecordedReadings) {
  BagMessages messages;
  for (int i = 0; i <= 4; ++i) {
    const double t = 10.0 + 0.5 * i;
    messages.poses["/odom"].push_back(BagStampedPose{t, t, "odom", "base_link", BagPose{double(i), 0, 0, 0, 0, 0, 1}});
  }
  messages.scans = {Scan(10.25, 10.25), Scan(11.0, 11.0)};
  const Sequence sequence = ReadMessages(messages);
  ASSERT_EQ(sequence.scans.size(), 2u);
  EXPECT_EQ(sequence.odometry.poses()[0].position.x(), 0.5);  // interpolated at 10.25
  EXPECT_EQ(sequence.odometry.poses()[1].position.x(), 2.0);  // the reading at 11.0
  // The five readings and the scan at 10.25 between two of them.
  EXPECT_EQ(sequence.odometry_readings.stamps_s(), (std::vector<double>{10.0, 10.25, 10.5, 11.0, 11.5, 12.0}));
  EXPECT_TRUE(sequence.warnings.empty());
}

TEST(BagSequenceTest, HeaderStampsFarFromTheRecordTimesAreNamedButUsed) {
  BagMessages messages;
  for (int i = 0; i <= 2; ++i) {
    const double t = 900.0 + i;
    messages.poses["/odom"].push_back(BagStampedPose{t, t + 1.0e6, "odom", "base_link", BagPose{}});
  }
  messages.scans = {Scan(900.5, 1.0e6 + 900.5), Scan(901.5, 1.0e6 + 901.5)};
  const Sequence sequence = ReadMessages(messages);
  EXPECT_EQ(sequence.scans.front().stamp_s, 900.5);
  ASSERT_EQ(sequence.warnings.size(), 1u);
  EXPECT_THAT(sequence.warnings[0], HasSubstr("hand.mcap: header.stamp of '/scan' differs from the bag's record time "
                                              "by 1000000.000 s (median"));
}

}  // namespace
}  // namespace slamsweep::evaluator
