// MCAP bags written by foxglove's npm writer (@mcap/core, @foxglove/rosmsg2-serialization) from a raw CARMEN
// log read back to the scans and poses slamsweep's CARMEN reader gives; and slamsweep's own bags read by the npm
// reader to the values they were written from.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/bag/bag_conversions.h"
#include "evaluator/formats/rosbag2/mapped_file.h"
#include "evaluator/formats/rosbag2/mcap_reader.h"
#include "evaluator/formats/rosbag2/rosbag2_reader.h"
#include "evaluator/formats/rosbag2/rosbag2_writer.h"
#include "evaluator/sequence_io/robot_log_file.h"
#include "evaluator/sequence_io/sequence_file.h"
#include "tests/evaluator/formats/rosbag2/bag_fixtures.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

struct NpmBag {
  const char* name;
  const char* options;
  bool indexed;
};

class NpmWrittenBagTest : public ::testing::TestWithParam<NpmBag> {};

TEST_P(NpmWrittenBagTest, ReadsBackToTheScansAndOdometryOfTheLog) {
  REQUIRE_CARMEN_FIXTURE();
  REQUIRE_NPM_TOOLS();
  const std::filesystem::path log = testing::RawCarmenLog().log;
  const std::filesystem::path bag = testing::FixtureDir() / (std::string(GetParam().name) + ".mcap");
  testing::RunBagTool("write-carmen '" + log.string() + "' '" + bag.string() + "' " + GetParam().options);
  const MappedFile file(bag);
  EXPECT_EQ(McapReader(file.Bytes(), bag.string()).Contents().indexed, GetParam().indexed);
  const Sequence from_log = ReadSequence(log);
  const Sequence from_bag = ReadSequence(bag);
  EXPECT_EQ(from_bag.name, GetParam().name);
  testing::ExpectSameRobotData(from_log, from_bag);
  EXPECT_TRUE(from_bag.warnings.empty()) << from_bag.warnings.front();
}

INSTANTIATE_TEST_SUITE_P(Chunks, NpmWrittenBagTest,
                         ::testing::Values(NpmBag{"uncompressed", "", true}, NpmBag{"zstd", "--compression zstd", true},
                                           NpmBag{"lz4", "--compression lz4", true},
                                           NpmBag{"unchunked", "--no-chunks", false},
                                           NpmBag{"no_summary", "--compression zstd --no-summary", false}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(NpmWrittenBagTest, AChunkOfAnUnknownCompressionNamesIt) {
  REQUIRE_CARMEN_FIXTURE();
  REQUIRE_NPM_TOOLS();
  const std::filesystem::path bag = testing::FixtureDir() / "brotli.mcap";
  testing::RunBagTool("write-carmen '" + testing::RawCarmenLog().log.string() + "' '" + bag.string() +
                      "' --compression brotli");
  EXPECT_THAT([&] { ReadSequence(bag); }, ::testing::ThrowsMessage<InputError>(AllOf(
                                              HasSubstr(bag.string() + ": Chunk record at byte "),
                                              HasSubstr("unknown compression 'brotli' (expected none, zstd or lz4)"))));
}

// A bag folder of MCAP split files as rosbag2 records them: the npm writer's two halves of the log (/tf_static in
// the first) in a folder with Python's metadata.yaml (version 9, storage mcap), plain and compressed per file
// with zstd (NAME_K.mcap.zstd, compression_mode FILE): the same scans and odometry as the log.
TEST(NpmWrittenBagTest, AnMcapFolderSplitInTwoPlainOrCompressedPerFile) {
  REQUIRE_CARMEN_FIXTURE();
  REQUIRE_NPM_TOOLS();
  const std::filesystem::path log = testing::RawCarmenLog().log;
  const Sequence from_log = ReadSequence(log);
  const std::filesystem::path single = testing::FixtureDir() / "mcap_whole.mcap";
  testing::RunBagTool("write-carmen '" + log.string() + "' '" + single.string() + "' --compression lz4");
  const Rosbag2Bag whole(single);
  ASSERT_EQ(whole.Summary().topics.size(), 3u);
  for (const std::string mode : {"", "FILE"}) {
    const std::string name = mode.empty() ? "mcap_split" : "mcap_split_zstd";
    const std::filesystem::path folder = testing::FixtureDir() / name;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    for (int part = 0; part < 2; ++part) {
      testing::RunBagTool("write-carmen '" + log.string() + "' '" +
                          (folder / (name + "_" + std::to_string(part) + ".mcap")).string() +
                          "' --compression lz4 --part " + std::to_string(part) + "/2");
    }
    ASSERT_EQ(testing::RunCommand(std::string(SLAMSWEEP_SYSTEM_PYTHON) + " '" + SLAMSWEEP_ROS2_BAGS_SCRIPT +
                                      "' --mcap-folder '" + log.string() + "' '" + folder.string() + "' 2 " + mode,
                                  folder.parent_path() / (name + ".log")),
              "");
    ASSERT_EQ(std::filesystem::exists(folder / (name + "_1.mcap.zstd")), !mode.empty()) << name;
    const Rosbag2Bag bag(folder);
    ASSERT_EQ(bag.Summary().topics.size(), 3u) << name;
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(bag.Summary().topics[i].topic, whole.Summary().topics[i].topic) << name;
      EXPECT_EQ(bag.Summary().topics[i].message_count, whole.Summary().topics[i].message_count) << name;
    }
    const Sequence from_bag = ReadSequence(folder);
    testing::ExpectSameRobotData(from_log, from_bag);
    EXPECT_TRUE(from_bag.warnings.empty()) << from_bag.warnings.front();
  }
}

/// A robot log's scans and odometry as written and the npm reader's decoding of them.
class OurBagsReadByNpmTest : public ::testing::Test {
 protected:
  void SetUp() override {
    REQUIRE_CARMEN_FIXTURE();
    source_ = ReadSequence(testing::RawCarmenLog().log);
    reference_ = source_.odometry;  // any trajectory: the bag's /ground_truth
  }
  Sequence source_;
  Trajectory reference_;
};

TEST_F(OurBagsReadByNpmTest, ScansOdometryTfAndGroundTruth) {
  REQUIRE_NPM_TOOLS();
  const std::filesystem::path folder = testing::FixtureDir() / "ours_for_npm";
  WriteRosbag2(RobotLogOf(source_), reference_, folder, Rosbag2StorageKind::kMcap);
  const std::filesystem::path file = folder / "ours_for_npm_0.mcap";
  const nlohmann::json npm = testing::NpmDump(file, "/scan /odom /tf /tf_static /ground_truth");
  EXPECT_EQ(npm.at("profile"), "ros2");
  EXPECT_TRUE(npm.at("indexed").get<bool>());
  const nlohmann::json& scans = npm.at("messages").at("/scan");
  ASSERT_EQ(scans.size(), source_.scans.size());
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const LaserScan& scan = source_.scans[i];
    const RosTime stamp = ToRosTime(scan.stamp_s, "test");
    ASSERT_EQ(scans[i].at("stamp"), nlohmann::json::array({stamp.sec, stamp.nanosec})) << i;
    ASSERT_EQ(scans[i].at("log_time").get<std::string>(), std::to_string(stamp.Nanoseconds())) << i;
    ASSERT_EQ(scans[i].at("frame_id"), "laser");
    ASSERT_EQ(scans[i].at("angle_min").get<double>(), static_cast<double>(static_cast<float>(scan.angle_min_rad)));
    ASSERT_EQ(scans[i].at("angle_increment").get<double>(),
              static_cast<double>(static_cast<float>(scan.angle_increment_rad)));
    ASSERT_EQ(scans[i].at("range_max").get<double>(), static_cast<double>(static_cast<float>(scan.range_max_m)));
    const std::vector<float> ranges(scans[i].at("ranges").begin(), scans[i].at("ranges").end());
    ASSERT_EQ(ranges, scan.ranges_m) << i;
  }
  // /odom: every reading, each scan's pose among them; /tf the same as transforms.
  const nlohmann::json& odometry = npm.at("messages").at("/odom");
  ASSERT_EQ(odometry.size(), source_.odometry_readings.size());
  ASSERT_EQ(npm.at("messages").at("/tf").size(), odometry.size());
  for (std::size_t i = 0; i < odometry.size(); ++i) {
    const Pose& pose = source_.odometry_readings.poses()[i];
    const std::vector<double> expected = {pose.position.x(),    pose.position.y(),    pose.position.z(),
                                          pose.orientation.x(), pose.orientation.y(), pose.orientation.z(),
                                          pose.orientation.w()};
    ASSERT_EQ(odometry[i].at("pose").get<std::vector<double>>(), expected) << i;
    ASSERT_EQ(odometry[i].at("frame_id"), "odom");
    ASSERT_EQ(odometry[i].at("child_frame_id"), "base_link");
    const nlohmann::json& transform = npm.at("messages").at("/tf")[i].at("transforms")[0];
    ASSERT_EQ(transform.at("pose").get<std::vector<double>>(), expected) << i;
    ASSERT_EQ(transform.at("child_frame_id"), "base_link");
  }
  const nlohmann::json& statics = npm.at("messages").at("/tf_static");
  ASSERT_EQ(statics.size(), 1u);
  EXPECT_EQ(statics[0].at("transforms")[0].at("frame_id"), "base_link");
  EXPECT_EQ(statics[0].at("transforms")[0].at("child_frame_id"), "laser");
  const nlohmann::json& truth = npm.at("messages").at("/ground_truth");
  ASSERT_EQ(truth.size(), reference_.size());
  EXPECT_EQ(truth[0].at("frame_id"), "map");
  EXPECT_EQ(truth.back().at("pose")[0].get<double>(), reference_.poses().back().position.x());
}

TEST_F(OurBagsReadByNpmTest, AProgramInputHasNoGroundTruth) {
  REQUIRE_NPM_TOOLS();
  const std::filesystem::path folder = testing::FixtureDir() / "program_input";
  WriteRobotLog(RobotLogOf(source_), folder, SequenceWriteFormat::kRosbag2);
  const nlohmann::json npm = testing::NpmDump(folder / "program_input_0.mcap", "");
  std::vector<std::string> topics;
  for (const nlohmann::json& topic : npm.at("topics")) topics.push_back(topic.at("topic"));
  EXPECT_EQ(topics, (std::vector<std::string>{"/odom", "/scan", "/tf", "/tf_static"}));
}

TEST_F(OurBagsReadByNpmTest, RoundTripsThroughBothStorages) {
  for (const Rosbag2StorageKind storage : {Rosbag2StorageKind::kMcap, Rosbag2StorageKind::kSqlite3}) {
    const std::filesystem::path folder =
        testing::FixtureDir() / ("round_trip_" + std::string(Rosbag2StorageName(storage)));
    WriteRosbag2(RobotLogOf(source_), reference_, folder, storage);
    BagReadOptions options;
    options.choices.reference_topic = "/ground_truth";
    const Sequence read = ReadRosbag2(folder, options);
    EXPECT_EQ(read.name, folder.filename().string());
    testing::ExpectSameRobotData(source_, read);
    ASSERT_TRUE(read.reference.has_value());
    EXPECT_EQ(read.reference->stamps_s(), reference_.stamps_s());
    // Without a choice, two Odometry topics: an error listing them.
    EXPECT_THAT([&] { ReadRosbag2(folder); },
                ::testing::ThrowsMessage<InputError>(HasSubstr("2 nav_msgs/Odometry topics (/ground_truth, /odom)")));
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
