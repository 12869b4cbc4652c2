#include "evaluator/formats/trajectory/carmen_log.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <numbers>
#include <string>

#include "tests/evaluator/formats/trajectory/trajectory_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using testing_util::ExpectInputError;
using testing_util::SamePose;

constexpr const char* kLog =
    "# message formats defined: PARAM SYNC ODOM FLASER RLASER\n"
    "PARAM robot_frontlaser_offset 0.0 nohost 0\n"
    "ODOM 0.5 0.25 0.1 0.3 0.02 0 12.5 pippo 12.6\n"
    "FLASER 3 1.5 2.5 81.91 1 2 0.5 1.1 2.1 0.6 13.25 pippo 13.3\n"
    "NEFF 31.5\n"
    "RLASER 2 4.0 5.5 3 4 -2.5 3.1 4.1 -2.4 1 h 1.5\n"
    "ROBOTLASER1 0 -1.5708 3.14159 0.0174533 81.9 0.01 0 2 3.5 4.5 1 200 0.1 0.2 0.3 1 2 0.25 0.4 0.05 1 0.5 0 "
    "14.75 b21 14.8\n";

TEST(CarmenLogTest, ParsesEachMessageItsOwnWay) {
  const CarmenLog log = ParseCarmenLog(kLog, "mem.log");
  ASSERT_EQ(log.params.size(), 1u);
  EXPECT_EQ(log.params[0].name, "robot_frontlaser_offset");
  EXPECT_EQ(log.params[0].value, "0.0");
  EXPECT_EQ(log.params[0].line, 2u);

  ASSERT_EQ(log.odometry.size(), 1u);
  EXPECT_TRUE(SamePose(Pose::Planar(0.5, 0.25, 0.1), log.odometry[0].pose, 1e-15));
  EXPECT_EQ(log.odometry[0].tv_mps, 0.3);
  EXPECT_EQ(log.odometry[0].rv_radps, 0.02);
  EXPECT_EQ(log.odometry[0].ipc_stamp_s, 12.5);
  EXPECT_EQ(log.odometry[0].ipc_host, "pippo");
  EXPECT_EQ(log.odometry[0].logger_stamp_s, 12.6);

  ASSERT_EQ(log.lasers.size(), 3u);
  const CarmenLaserRecord& flaser = log.lasers[0];
  EXPECT_EQ(flaser.type, "FLASER");
  EXPECT_EQ(flaser.ranges_m, (std::vector<double>{1.5, 2.5, 81.91}));
  EXPECT_TRUE(SamePose(Pose::Planar(1, 2, 0.5), flaser.robot_pose, 1e-15));
  EXPECT_TRUE(SamePose(Pose::Planar(1.1, 2.1, 0.6), flaser.odom_pose, 1e-15));
  EXPECT_FALSE(flaser.geometry.has_value());
  EXPECT_EQ(flaser.ipc_stamp_s, 13.25);
  EXPECT_EQ(flaser.line, 4u);

  // The rear laser has FLASER's layout.
  const CarmenLaserRecord& rlaser = log.lasers[1];
  EXPECT_EQ(rlaser.type, "RLASER");
  EXPECT_EQ(rlaser.ranges_m, (std::vector<double>{4.0, 5.5}));
  EXPECT_TRUE(SamePose(Pose::Planar(3, 4, -2.5), rlaser.robot_pose, 1e-15));
  EXPECT_TRUE(SamePose(Pose::Planar(3, 4, -2.5), rlaser.laser_pose, 1e-15));
  EXPECT_TRUE(SamePose(Pose::Planar(3.1, 4.1, -2.4), rlaser.odom_pose, 1e-15));
  EXPECT_FALSE(rlaser.geometry.has_value());
  EXPECT_EQ(rlaser.ipc_stamp_s, 1.0);
  EXPECT_EQ(rlaser.ipc_host, "h");
  EXPECT_EQ(rlaser.logger_stamp_s, 1.5);
  EXPECT_EQ(rlaser.line, 6u);

  const CarmenLaserRecord& robot = log.lasers[2];
  EXPECT_EQ(robot.type, "ROBOTLASER1");
  EXPECT_EQ(robot.ranges_m, (std::vector<double>{3.5, 4.5}));
  EXPECT_EQ(robot.remissions, (std::vector<double>{200}));
  ASSERT_TRUE(robot.geometry.has_value());
  EXPECT_EQ(robot.geometry->start_angle_rad, -1.5708);
  EXPECT_EQ(robot.geometry->fov_rad, 3.14159);
  EXPECT_EQ(robot.geometry->max_range_m, 81.9);
  EXPECT_TRUE(SamePose(Pose::Planar(0.1, 0.2, 0.3), robot.laser_pose, 1e-15));
  EXPECT_TRUE(SamePose(Pose::Planar(1, 2, 0.25), robot.robot_pose, 1e-15));
  EXPECT_EQ(robot.ipc_stamp_s, 14.75);
  EXPECT_EQ(robot.ipc_host, "b21");
  EXPECT_EQ(robot.line, 7u);

  EXPECT_EQ(log.skipped_messages.at("NEFF"), 1u);
  EXPECT_EQ(log.skipped_messages.count("RLASER"), 0u);
}

TEST(CarmenLogTest, FormattedRecordsReadBack) {
  const CarmenLog log = ParseCarmenLog(kLog, "mem.log");
  std::string text;
  for (const CarmenParam& param : log.params) text += FormatCarmenRecord(param) + "\n";
  for (const CarmenOdomRecord& odom : log.odometry) text += FormatCarmenRecord(odom) + "\n";
  for (const CarmenLaserRecord& laser : log.lasers) text += FormatCarmenRecord(laser) + "\n";
  const CarmenLog again = ParseCarmenLog(text, "again.log");
  ASSERT_EQ(again.lasers.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const CarmenLaserRecord& a = log.lasers[i];
    const CarmenLaserRecord& b = again.lasers[i];
    EXPECT_EQ(a.type, b.type);
    EXPECT_EQ(a.ranges_m, b.ranges_m);
    EXPECT_EQ(a.remissions, b.remissions);
    EXPECT_TRUE(SamePose(a.robot_pose, b.robot_pose, 1e-15));
    EXPECT_TRUE(SamePose(a.laser_pose, b.laser_pose, 1e-15));
    EXPECT_TRUE(SamePose(a.odom_pose, b.odom_pose, 1e-15));
    EXPECT_EQ(a.ipc_stamp_s, b.ipc_stamp_s);
    EXPECT_EQ(a.ipc_host, b.ipc_host);
    EXPECT_EQ(a.logger_stamp_s, b.logger_stamp_s);
  }
  EXPECT_EQ(again.lasers[2].geometry->angular_resolution_rad, log.lasers[2].geometry->angular_resolution_rad);
  ASSERT_EQ(again.odometry.size(), 1u);
  EXPECT_EQ(again.odometry[0].tv_mps, 0.3);
  EXPECT_EQ(again.params[0].value, "0.0");
}

std::string FlaserWithBeams(int declared, int given) {
  std::string line = "FLASER " + std::to_string(declared);
  for (int i = 0; i < given; ++i) line += " 1.5";
  return line + " 1 2 0.5 1 2 0.5 13.25 pippo 13.3\n";
}

TEST(CarmenLogTest, WrongBeamCountNamesFileAndLine) {
  ASSERT_NO_THROW(ParseCarmenLog(FlaserWithBeams(180, 180), "ok.log"));
  ExpectInputError([] { ParseCarmenLog("PARAM a b\n" + FlaserWithBeams(180, 179), "beams.log"); },
                   {"beams.log:2", "num_readings = 180", "191 fields", "got 190"});
  ExpectInputError([] { ParseCarmenLog(FlaserWithBeams(-3, 0), "beams.log"); }, {"beams.log:1", ">= 0"});
  ExpectInputError([] { ParseCarmenLog(FlaserWithBeams(999999999, 2), "beams.log"); }, {"beams.log:1", "999999999"});
  ExpectInputError([] { ParseCarmenLog("FLASER x 1 2\n", "beams.log"); }, {"beams.log:1", "num_readings", "integer"});
}

TEST(CarmenLogTest, BadRearLaserRecordsNameTheMessage) {
  ExpectInputError([] { ParseCarmenLog("RLASER 3 1 2 1 2 0.5 1 2 0.5 13.25 pippo 13.3\n", "rear.log"); },
                   {"rear.log:1", "RLASER with num_readings = 3", "RLASER n r1..rn"});
  ExpectInputError(
      [] { ParseCarmenLog("ODOM 0 0 0 0 0 0 1 h 1\nRLASER 2 1 x 1 2 0.5 1 2 0.5 13.25 pippo 13.3\n", "rear.log"); },
      {"rear.log:2", "range"});
}

TEST(CarmenLogTest, BadFieldsNameFileAndLine) {
  ExpectInputError([] { ParseCarmenLog("FLASER 2 1.5 abc 1 2 0.5 1 2 0.5 13.25 pippo 13.3\n", "bad.log"); },
                   {"bad.log:1", "range", "'abc'"});
  ExpectInputError([] { ParseCarmenLog("FLASER 2 1.5 2 1 nan 0.5 1 2 0.5 13.25 pippo 13.3\n", "bad.log"); },
                   {"bad.log:1", "(y)"});
  ExpectInputError([] { ParseCarmenLog("# c\nFLASER 2 1.5 2 1 2 0.5 1 2 0.5 13.25\n", "bad.log"); },
                   {"bad.log:2", "13 fields", "got 11"});
  ExpectInputError([] { ParseCarmenLog("ODOM 0.5 0.25 0.1 0.3 0.02 0 12.5 pippo\n", "bad.log"); },
                   {"bad.log:1", "ODOM", "10 fields", "got 9"});
  ExpectInputError([] { ParseCarmenLog("ODOM 0.5 0.25 0.1 0.3 0.02 0 t pippo 1\n", "bad.log"); },
                   {"bad.log:1", "ipc_timestamp"});
  ExpectInputError([] { ParseCarmenLog("PARAM lonely\n", "bad.log"); }, {"bad.log:1", "PARAM name value"});
  // ROBOTLASER1 with 2 readings declared but a line cut after the ranges.
  ExpectInputError([] { ParseCarmenLog("ROBOTLASER1 0 -1.5 3.1 0.01 81.9 0.01 0 2 3.5 4.5 0 0.1 0.2\n", "bad.log"); },
                   {"bad.log:1", "ROBOTLASER1 with num_readings = 2", "26 fields"});
}

TEST(CarmenLogTest, EmptyLogHasNoRecords) {
  const CarmenLog log = ParseCarmenLog("", "empty.log");
  EXPECT_TRUE(log.lasers.empty());
  EXPECT_TRUE(log.odometry.empty());
}

TEST(CarmenLogTest, GzipBeyondTheInflateCapIsAnErrorNamingTheFile) {
  testing::TempDir dir;
  const std::filesystem::path path = dir / "bomb.log.gz";
  // 17 MiB of comment lines compress to about 17 KiB: beyond the 16 MiB cap.
  const std::string comments(std::size_t{17} << 20, '#');
  gzFile file = gzopen(path.c_str(), "wb");
  gzwrite(file, comments.data(), static_cast<unsigned>(comments.size()));
  gzclose(file);
  ExpectInputError([&] { ReadCarmenLog(path); }, {"bomb.log.gz", "inflates to more than 16.0 MiB"});
}

}  // namespace
}  // namespace slamsweep::evaluator
