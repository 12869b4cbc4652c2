#include "evaluator/sequence_io/sequence_file.h"
#include "evaluator/sequence_io/robot_log_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "tests/support/shared_data.h"
#include "tests/support/input_error_text.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

using slamsweep::testing::ErrorOf;

/// Three scans of a CARMEN front laser (181 beams, -90..+90 deg, sensor at the robot origin) with a
/// reference that differs from the odometry, and one no-return beam per scan.
Sequence CarmenLikeSequence() {
  Sequence sequence;
  sequence.name = "hand";
  Trajectory reference;
  for (int i = 0; i < 3; ++i) {
    LaserScan scan;
    scan.stamp_s = 100.25 + 0.5 * i;
    scan.angle_min_rad = -std::numbers::pi / 2;
    scan.angle_increment_rad = std::numbers::pi / 180;
    scan.range_max_m = 50.0;
    for (int b = 0; b < 181; ++b) scan.ranges_m.push_back(0.1f * static_cast<float>(b + i) + 0.013f);
    scan.ranges_m[7] = 81.91f;
    sequence.scans.push_back(scan);
    sequence.odometry.Add(scan.stamp_s, Pose::Planar(1.0 + i, 2.0, 0.1 * i));
    reference.Add(scan.stamp_s, Pose::Planar(1.1 + i, 2.2, 0.1 * i + 0.05));
  }
  sequence.reference = reference;
  return sequence;
}

void ExpectSamePoses(const Trajectory& actual, const Trajectory& expected, double tolerance) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    EXPECT_EQ(actual.stamps_s()[i], expected.stamps_s()[i]);
    EXPECT_NEAR((actual.poses()[i].position - expected.poses()[i].position).norm(), 0.0, tolerance) << i;
    EXPECT_NEAR(NormalizeAngleRad(actual.poses()[i].Yaw() - expected.poses()[i].Yaw()), 0.0, tolerance) << i;
  }
}

TEST(SequenceFileTest, CarmenFlaserRoundTripKeepsScansAndOdometryAndNoReference) {
  testing::TempDir dir;
  const Sequence written = CarmenLikeSequence();
  WriteRobotLog(RobotLogOf(written), dir / "hand.log", SequenceWriteFormat::kCarmen);
  const std::string text = FormatCarmenLog(RobotLogOf(written));
  EXPECT_THAT(text, HasSubstr("PARAM robot_front_laser_max 50\n"));
  EXPECT_THAT(text, HasSubstr("FLASER 181 0.013 "));  // shortest text of the float, not its double expansion

  const Sequence read = ReadSequence(dir / "hand.log");
  ASSERT_EQ(read.scans.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(read.scans[i].ranges_m, written.scans[i].ranges_m) << i;  // bit for bit
    EXPECT_EQ(read.scans[i].stamp_s, written.scans[i].stamp_s);
    EXPECT_DOUBLE_EQ(read.scans[i].angle_min_rad, -std::numbers::pi / 2);
    EXPECT_DOUBLE_EQ(read.scans[i].angle_increment_rad, std::numbers::pi / 180);
    EXPECT_EQ(read.scans[i].range_max_m, 50.0);
    EXPECT_FALSE(read.scans[i].IsHit(read.scans[i].ranges_m[7]));
  }
  ExpectSamePoses(read.odometry, written.odometry, 1e-12);
  // A program input is a raw robot log: its logged poses are odometry, read back as no reference.
  EXPECT_FALSE(read.reference.has_value());
  EXPECT_TRUE(read.warnings.empty());
}

TEST(SequenceFileTest, CarmenRobotLaserRoundTripKeepsAnyFanAndTheMount) {
  testing::TempDir dir;
  Sequence written = CarmenLikeSequence();
  written.reference.reset();
  for (LaserScan& scan : written.scans) {
    scan.ranges_m.resize(360);
    scan.angle_min_rad = -std::numbers::pi;
    scan.angle_increment_rad = 2 * std::numbers::pi / 360;
    scan.sensor_pose_on_robot = Pose::Planar(0.2, -0.05, 0.1);
  }
  const std::string text = FormatCarmenLog(RobotLogOf(written));
  EXPECT_THAT(text, HasSubstr("ROBOTLASER1 "));
  EXPECT_THAT(text, ::testing::Not(HasSubstr("FLASER")));
  WriteRobotLog(RobotLogOf(written), dir / "any.log", SequenceWriteFormat::kCarmen);
  const Sequence read = ReadSequence(dir / "any.log");
  ASSERT_EQ(read.scans.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(read.scans[i].ranges_m, written.scans[i].ranges_m);
    EXPECT_DOUBLE_EQ(read.scans[i].angle_min_rad, -std::numbers::pi);
    EXPECT_DOUBLE_EQ(read.scans[i].angle_increment_rad, 2 * std::numbers::pi / 360);
    EXPECT_EQ(read.scans[i].range_max_m, 50.0);
    EXPECT_NEAR(read.scans[i].sensor_pose_on_robot.position.x(), 0.2, 1e-12);
    EXPECT_NEAR(read.scans[i].sensor_pose_on_robot.position.y(), -0.05, 1e-12);
    EXPECT_NEAR(read.scans[i].sensor_pose_on_robot.Yaw(), 0.1, 1e-12);
  }
  ExpectSamePoses(read.odometry, written.odometry, 1e-12);
}

TEST(SequenceFileTest, TumProgramInputIsTheOdometry) {
  testing::TempDir dir;
  const Sequence sequence = CarmenLikeSequence();
  ASSERT_TRUE(sequence.reference.has_value());
  WriteRobotLog(RobotLogOf(sequence), dir / "odo.tum", SequenceWriteFormat::kTum);
  ExpectSamePoses(ReadTum(dir / "odo.tum"), sequence.odometry, 1e-12);
}

TEST(SequenceFileTest, RawlogRoundTripWhenMrptIsBuilt) {
  if (!RawlogSupported()) {
    testing::TempDir dir;
    EXPECT_THAT(ErrorOf([&] {
                  WriteRobotLog(RobotLogOf(CarmenLikeSequence()), dir / "x.rawlog", SequenceWriteFormat::kRawlog);
                }),
                HasSubstr("MRPT rawlog support not built"));
    SLAMSWEEP_SKIP_OR_FAIL_IN_CI("MRPT not built (Debian: libmrpt-obs-dev, scripts/install-deps.sh)");
  }
  testing::TempDir dir;
  const Sequence written = CarmenLikeSequence();
  WriteRobotLog(RobotLogOf(written), dir / "hand.rawlog", SequenceWriteFormat::kRawlog);
  EXPECT_EQ(DetectSequenceFormat(dir / "hand.rawlog"), SequenceFormat::kRawlog);
  const Sequence read = ReadSequence(dir / "hand.rawlog");
  ASSERT_EQ(read.scans.size(), 3u);
  EXPECT_FALSE(read.reference.has_value());  // a rawlog holds none
  for (std::size_t i = 0; i < 3; ++i) {
    ASSERT_EQ(read.scans[i].BeamCount(), 181u);
    EXPECT_NEAR(read.scans[i].stamp_s, written.scans[i].stamp_s, 1e-6);
    EXPECT_EQ(read.scans[i].ranges_m[20], written.scans[i].ranges_m[20]);
    EXPECT_FALSE(read.scans[i].IsHit(read.scans[i].ranges_m[7]));
  }
  ExpectSamePoses(read.odometry, written.odometry, 1e-6);
}

TEST(SequenceFileTest, FormatComesFromTheExtensionThenTheContent) {
  testing::TempDir dir;
  const std::string carmen = FormatCarmenLog(RobotLogOf(CarmenLikeSequence()));
  EXPECT_EQ(DetectSequenceFormat(testing::WriteFile(dir / "a.clf", carmen)), SequenceFormat::kCarmen);
  // GMapping's .gfs output is not a CARMEN log: only the content can make it one.
  EXPECT_EQ(DetectSequenceFormat(testing::WriteFile(dir / "a.gfs", carmen)), SequenceFormat::kCarmen);
  EXPECT_EQ(DetectSequenceFormat(testing::WriteFile(dir / "no_extension", carmen)), SequenceFormat::kCarmen);
  EXPECT_EQ(DetectSequenceFormat(testing::WriteFile(dir / "x.bag", "#ROSBAG V2.0\n")), SequenceFormat::kRosbag);
  EXPECT_EQ(DetectSequenceFormat(testing::WriteFile(dir / "bag_without_extension", "#ROSBAG V2.0\n")),
            SequenceFormat::kRosbag);
  EXPECT_THAT(ErrorOf([&] { DetectSequenceFormat(testing::WriteFile(dir / "notes.txt", "hello world\n")); }),
              HasSubstr("notes.txt: unknown sequence format"));
  EXPECT_THAT(ErrorOf([&] { ReadSequence(dir / "missing.log"); }), HasSubstr("missing.log: no such file"));
}

TEST(SequenceFileTest, FormatNamesAreCheckedAndTheOptionNamed) {
  EXPECT_EQ(ParseSequenceWriteFormat("rawlog"), SequenceWriteFormat::kRawlog);
  EXPECT_EQ(ParseSequenceWriteFormat("carmen"), SequenceWriteFormat::kCarmen);
  EXPECT_EQ(ParseSequenceWriteFormat("tum"), SequenceWriteFormat::kTum);
  EXPECT_THAT(ErrorOf([] { ParseSequenceWriteFormat("png"); }),
              HasSubstr("--to: expected rawlog, carmen, tum or rosbag2"));
  EXPECT_EQ(ParseSequenceFormat("rosbag"), SequenceFormat::kRosbag);
  EXPECT_THAT(ErrorOf([] { ParseSequenceFormat("kitti", "format"); }), HasSubstr("format: expected"));
}

TEST(SequenceFileTest, Fr079ReadsWithTheCountsOfItsProvenance) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/fr079/freiburg-079-corrected.log.gz");
  const Sequence sequence = ReadSequence(log);
  EXPECT_EQ(sequence.scans.size(), 4791u);  // PROVENANCE.txt: FLASER=4791 readings=[360]
  for (const LaserScan& scan : sequence.scans) ASSERT_EQ(scan.BeamCount(), 360u);
  EXPECT_NO_THROW(ValidateSequence(sequence));
}

// ---- the fast CARMEN reader agrees with the checked one ----

/// Writes `text` gzip-compressed.
void WriteGzip(const std::filesystem::path& path, const std::string& text) {
  gzFile file = gzopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  gzwrite(file, text.data(), static_cast<unsigned>(text.size()));
  gzclose(file);
}

TEST(CarmenFastReadTest, EveryNumberFormReadsAsStrtodReadsIt) {
  // Forms the fast decimal path takes and forms it leaves to from_chars (exponents, 20 digits, '5.').
  const std::vector<std::string> forms = {"0",
                                          "-0",
                                          "1.5",
                                          "-2.25",
                                          "0.1",
                                          "81.91",
                                          "1e-3",
                                          "2.5E+1",
                                          "5.",
                                          ".5",
                                          "0.12345678901234567890",
                                          "123456789012345678",
                                          "32.767",
                                          "1.13486e+09"};
  std::string line = "FLASER " + std::to_string(forms.size());
  for (const std::string& form : forms) line += ' ' + form;
  line += " 1 2 3 4 5 6 7.25 host 8\n";
  const CarmenLog log = ParseCarmenLog(line, "forms.log");
  ASSERT_EQ(log.lasers.size(), 1u);
  for (std::size_t i = 0; i < forms.size(); ++i) {
    EXPECT_EQ(log.lasers[0].ranges_m[i], std::strtod(forms[i].c_str(), nullptr)) << forms[i];
  }
  EXPECT_EQ(log.lasers[0].ipc_stamp_s, 7.25);
}

TEST(CarmenFastReadTest, GzipLogsGiveTheLineOfABadFieldAndNameATruncatedFile) {
  testing::TempDir dir;
  std::string text = "# comment\n\nODOM 0 0 0 0 0 0 1 host 1\n";
  for (int i = 0; i < 4000; ++i) text += "FLASER 3 1 2 3 0 0 0 0 0 0 " + std::to_string(2 + i) + " host 0\n";
  text += "FLASER 3 1 x 3 0 0 0 0 0 0 9999 host 0\n";
  WriteGzip(dir / "bad.log.gz", text);
  const std::string expected_line =
      ":" + std::to_string(4000 + 4) + ": field 4 (range): expected a finite number, got 'x'";
  EXPECT_THAT(ErrorOf([&] { ReadCarmenLog(dir / "bad.log.gz"); }), HasSubstr(expected_line));

  WriteGzip(dir / "good.log.gz", text.substr(0, text.rfind("FLASER 3 1 x")));
  const CarmenLog good = ReadCarmenLog(dir / "good.log.gz");
  EXPECT_EQ(good.lasers.size(), 4000u);
  EXPECT_EQ(good.lasers.back().line, 4003u);
  EXPECT_EQ(good.odometry.size(), 1u);

  std::ifstream in(dir / "good.log.gz", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  testing::WriteFile(dir / "cut.log.gz", bytes.substr(0, bytes.size() / 2));
  const std::string error = ErrorOf([&] { ReadCarmenLog(dir / "cut.log.gz"); });
  EXPECT_THAT(error, HasSubstr("cut.log.gz"));
  EXPECT_THAT(error, HasSubstr("truncated"));
}

TEST(CarmenFastReadTest, ConcatenatedGzipMembersAreOneLog) {
  testing::TempDir dir;
  WriteGzip(dir / "a.gz", "FLASER 2 1 2 0 0 0 0 0 0 1 h 1\n");
  WriteGzip(dir / "b.gz", "FLASER 2 3 4 0 0 0 0 0 0 2 h 2\n");
  std::ifstream a(dir / "a.gz", std::ios::binary), b(dir / "b.gz", std::ios::binary);
  std::stringstream both;
  both << a.rdbuf() << b.rdbuf();
  testing::WriteFile(dir / "both.log.gz", both.str());
  const CarmenLog log = ReadCarmenLog(dir / "both.log.gz");
  ASSERT_EQ(log.lasers.size(), 2u);
  EXPECT_EQ(log.lasers[1].ranges_m[1], 4.0);
  EXPECT_EQ(log.lasers[1].line, 2u);
}

}  // namespace
}  // namespace slamsweep::evaluator
