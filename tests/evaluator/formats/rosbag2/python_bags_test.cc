// rosbag2 sqlite3 bags written by Python's sqlite3, struct and zstandard (make_ros2_bags.py) from a raw CARMEN
// log: every schema version, old metadata versions, a bag split in two, rosbag2's per-file and per-message zstd,
// big-endian CDR read back to the log's scans and odometry; the bad ones give an error naming the file and
// the record or topic. And slamsweep's sqlite3 bags read by Python (read_db3.py).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/bag/bag_conversions.h"
#include "evaluator/formats/rosbag2/rosbag2_reader.h"
#include "evaluator/formats/rosbag2/rosbag2_writer.h"
#include "evaluator/sequence_io/sequence_file.h"
#include "tests/evaluator/formats/rosbag2/bag_fixtures.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

/// The Python bags, written once; or why they could not be.
struct PythonBags {
  std::filesystem::path dir;
  std::string unavailable;
  std::string failed;
};

const PythonBags& Bags() {
  static const PythonBags bags = [] {
    PythonBags made;
    if (!testing::RawCarmenLog().why.empty()) {
      made.unavailable = testing::RawCarmenLog().why;
      return made;
    }
    made.dir = testing::FixtureDir() / "python";
    std::filesystem::create_directories(made.dir);
    const std::string python = SLAMSWEEP_SYSTEM_PYTHON;
    if (!testing::RunCommand(python + " -c 'import sqlite3, zstandard'", made.dir / "check.log").empty()) {
      made.unavailable = python +
                         " with sqlite3 and zstandard is not available (Debian: python3-zstandard; "
                         "scripts/install-deps.sh)";
      return made;
    }
    made.failed = testing::RunCommand(python + " '" + SLAMSWEEP_ROS2_BAGS_SCRIPT + "' '" +
                                          testing::RawCarmenLog().log.string() + "' '" + made.dir.string() + "'",
                                      made.dir / "make.log");
    return made;
  }();
  return bags;
}

#define REQUIRE_PYTHON_BAGS()                          \
  if (!Bags().failed.empty()) FAIL() << Bags().failed; \
  if (!Bags().unavailable.empty()) SLAMSWEEP_SKIP_OR_FAIL_IN_CI(Bags().unavailable)

class PythonWrittenBagTest : public ::testing::TestWithParam<const char*> {};

TEST_P(PythonWrittenBagTest, ReadsBackToTheScansAndOdometryOfTheLog) {
  REQUIRE_PYTHON_BAGS();
  const Sequence from_log = ReadSequence(testing::RawCarmenLog().log);
  const Sequence from_bag = ReadSequence(Bags().dir / GetParam());
  testing::ExpectSameRobotData(from_log, from_bag);
  EXPECT_TRUE(from_bag.warnings.empty()) << from_bag.warnings.front();
}

INSTANTIATE_TEST_SUITE_P(Storage, PythonWrittenBagTest,
                         ::testing::Values("schema1", "schema2", "schema3", "schema4", "split", "file_zstd",
                                           "message_zstd", "big_endian.db3", "schema3/schema3_0.db3"),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

TEST(PythonWrittenBagTest, TopicsAreMatchedByNameAcrossSplitFiles) {
  REQUIRE_PYTHON_BAGS();
  const Rosbag2Bag bag(Bags().dir / "split");
  const Rosbag2Bag whole(Bags().dir / "schema3");
  ASSERT_EQ(bag.Summary().topics.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(bag.Summary().topics[i].topic, whole.Summary().topics[i].topic);
    EXPECT_EQ(bag.Summary().topics[i].message_count, whole.Summary().topics[i].message_count);
  }
}

/// The error `path` gives when read as a sequence.
std::string ErrorOf(const std::filesystem::path& path) {
  try {
    ReadSequence(path);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(PythonWrittenBagTest, BadBagsNameTheFileAndWhatIsWrong) {
  REQUIRE_PYTHON_BAGS();
  const std::filesystem::path& dir = Bags().dir;
  EXPECT_THAT(ErrorOf(dir / "no_metadata"),
              AllOf(HasSubstr((dir / "no_metadata").string()), HasSubstr("no metadata.yaml in the folder")));
  EXPECT_THAT(ErrorOf(dir / "missing_split"),
              HasSubstr("split file missing_split_1.db3 named by metadata.yaml is missing"));
  EXPECT_THAT(ErrorOf(dir / "wrong_type"),
              AllOf(HasSubstr(": no sensor_msgs/LaserScan topic"), HasSubstr("/scan (nav_msgs/msg/Odometry)")));
  EXPECT_THAT(ErrorOf(dir / "unknown_compression"),
              AllOf(HasSubstr("metadata.yaml"), HasSubstr("unknown compression_format 'lz77'")));
  EXPECT_THAT(ErrorOf(dir / "unknown_encoding.db3"),
              AllOf(HasSubstr("unknown_encoding.db3: topic '/scan' is serialised as 'json'")));
  EXPECT_THAT(ErrorOf(dir / "xcdr2.db3"),
              AllOf(HasSubstr("xcdr2.db3: topic '/scan' message 0"), HasSubstr("CDR encapsulation is XCDR2")));
  EXPECT_THAT(ErrorOf(dir / "short_message.db3"),
              AllOf(HasSubstr("short_message.db3: topic '/scan' message 1: truncated CDR message")));
}

TEST(PythonWrittenBagTest, ATopicOfTheWrongTypeChosenByNameIsNamed) {
  REQUIRE_PYTHON_BAGS();
  SequenceReadOptions options;
  options.bag.scan_topic = "/odom";
  EXPECT_THAT([&] { ReadSequence(Bags().dir / "schema3", options); },
              ThrowsMessage<InputError>(
                  HasSubstr("scan topic '/odom' holds nav_msgs/msg/Odometry, expected sensor_msgs/msg/LaserScan")));
  options.bag.scan_topic.clear();
  options.bag.reference_topic = "/scan";
  EXPECT_THAT([&] { ReadSequence(Bags().dir / "schema3", options); },
              ThrowsMessage<InputError>(
                  HasSubstr("reference topic '/scan' holds sensor_msgs/msg/LaserScan, expected nav_msgs/msg/Odometry, "
                            "geometry_msgs/msg/PoseStamped or geometry_msgs/msg/PoseWithCovarianceStamped")));
}

TEST(PythonWrittenBagTest, ATruncatedDatabaseIsAnErrorNamingIt) {
  REQUIRE_PYTHON_BAGS();
  const std::filesystem::path source = Bags().dir / "schema3" / "schema3_0.db3";
  const std::filesystem::path cut = Bags().dir / "cut.db3";
  std::filesystem::copy_file(source, cut, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::resize_file(cut, std::filesystem::file_size(source) / 3);
  EXPECT_THAT(ErrorOf(cut), HasSubstr(cut.string() + ": "));
  std::filesystem::resize_file(cut, 10);
  EXPECT_THAT(ErrorOf(cut), HasSubstr("neither an MCAP file nor an SQLite database"));
}

TEST(OurSqliteBagsTest, ArePythonReadableAsHumbleWritesThem) {
  REQUIRE_PYTHON_BAGS();
  const Sequence source = ReadSequence(testing::RawCarmenLog().log);
  const std::filesystem::path folder = testing::FixtureDir() / "ours_sqlite3";
  WriteRosbag2(RobotLogOf(source), source.odometry, folder, Rosbag2StorageKind::kSqlite3);
  const std::filesystem::path out = testing::FixtureDir() / "ours_sqlite3.json";
  ASSERT_EQ(testing::RunCommand(std::string(SLAMSWEEP_SYSTEM_PYTHON) + " '" + SLAMSWEEP_READ_DB3_SCRIPT + "' '" +
                                    folder.string() + "' '" + out.string() + "'",
                                testing::FixtureDir() / "read_db3.log"),
            "");
  std::ifstream in(out);
  const nlohmann::json read = nlohmann::json::parse(in);
  EXPECT_EQ(read.at("metadata_version"), 5);
  EXPECT_EQ(read.at("storage"), "sqlite3");
  EXPECT_EQ(read.at("schema"), nlohmann::json::parse(R"([3, "humble"])"));
  EXPECT_EQ(read.at("stored_metadata_version"), 5);
  EXPECT_EQ(read.at("tables"), nlohmann::json::parse(R"(["messages", "metadata", "schema", "topics"])"));
  EXPECT_EQ(read.at("topics"), nlohmann::json::parse("[[\"/ground_truth\", \"nav_msgs/msg/Odometry\", \"cdr\", " +
                                                     std::to_string(source.odometry.size()) +
                                                     "], [\"/odom\", \"nav_msgs/msg/Odometry\", "
                                                     "\"cdr\", " +
                                                     std::to_string(source.odometry_readings.size()) +
                                                     "], [\"/scan\", \"sensor_msgs/msg/LaserScan\", \"cdr\", " +
                                                     std::to_string(source.scans.size()) +
                                                     "], [\"/tf\", \"tf2_msgs/msg/TFMessage\", "
                                                     "\"cdr\", " +
                                                     std::to_string(source.odometry_readings.size()) +
                                                     "], [\"/tf_static\", \"tf2_msgs/msg/TFMessage\", \"cdr\", 1]]"));
  const RosTime first = ToRosTime(source.scans.front().stamp_s, "test");
  EXPECT_EQ(read.at("first_scan").at("sec"), first.sec);
  EXPECT_EQ(read.at("first_scan").at("nanosec"), first.nanosec);
  EXPECT_EQ(read.at("first_scan").at("frame_id"), "laser");
  const std::vector<float> ranges(read.at("first_scan").at("ranges").begin(), read.at("first_scan").at("ranges").end());
  EXPECT_EQ(ranges, source.scans.front().ranges_m);
  const Pose& last = source.odometry_readings.poses().back();
  EXPECT_EQ(read.at("last_odom").at("pose").get<std::vector<double>>(),
            (std::vector<double>{last.position.x(), last.position.y(), last.position.z(), last.orientation.x(),
                                 last.orientation.y(), last.orientation.z(), last.orientation.w()}));
}

}  // namespace
}  // namespace slamsweep::evaluator
