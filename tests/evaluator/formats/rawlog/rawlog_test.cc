#include <gtest/gtest.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/rawlog/rawlog_reader.h"
#include "evaluator/formats/rawlog/rawlog_writer.h"
#include "evaluator/sequence/carmen_sequence.h"
#include "tests/evaluator/formats/rawlog/rawlog_test_util.h"
#include "tests/support/shared_data.h"
#include "tests/support/input_error_text.h"

namespace slamsweep::evaluator {
namespace {

using rawlog_testing::HaveProgram;
using rawlog_testing::SyntheticSequence;

constexpr const char* kMrptSample = "/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog";

/// World direction of beam i of a scan taken at `robot`.
double BeamHeadingRad(const Pose& robot, const LaserScan& scan, std::size_t i) {
  return NormalizeAngleRad((robot * scan.sensor_pose_on_robot).Yaw() + scan.BeamAngleRad(i));
}

double AngleDifferenceRad(double a, double b) { return std::abs(NormalizeAngleRad(a - b)); }

/// Everything a SLAM program sees of a scan must survive the round trip; the sensor frame may turn
/// (MRPT's fans are symmetric) but beams keep their directions and the laser its position.
void ExpectSameSequence(const Sequence& written, const Sequence& read) {
  ASSERT_EQ(read.scans.size(), written.scans.size());
  ASSERT_EQ(read.odometry.size(), written.scans.size());
  for (std::size_t s = 0; s < written.scans.size(); ++s) {
    const LaserScan& a = written.scans[s];
    const LaserScan& b = read.scans[s];
    SCOPED_TRACE("scan " + std::to_string(s));
    EXPECT_NEAR(b.stamp_s, a.stamp_s, 1e-6);
    EXPECT_EQ(read.odometry.stamps_s()[s], b.stamp_s);
    const Pose& pose_a = written.odometry.poses()[s];
    const Pose& pose_b = read.odometry.poses()[s];
    EXPECT_NEAR((pose_b.position - pose_a.position).norm(), 0.0, 1e-6);
    EXPECT_NEAR(AngleDifferenceRad(pose_b.Yaw(), pose_a.Yaw()), 0.0, 1e-6);
    EXPECT_NEAR(b.range_max_m, a.range_max_m, 1e-5);
    const Pose laser_a = pose_a * a.sensor_pose_on_robot;
    const Pose laser_b = pose_b * b.sensor_pose_on_robot;
    EXPECT_NEAR((laser_b.position - laser_a.position).norm(), 0.0, 1e-6);
    ASSERT_EQ(b.BeamCount(), a.BeamCount());
    for (std::size_t i = 0; i < a.BeamCount(); ++i) {
      ASSERT_EQ(b.IsHit(b.ranges_m[i]), a.IsHit(a.ranges_m[i])) << "beam " << i;
      if (a.IsHit(a.ranges_m[i])) {
        ASSERT_EQ(b.ranges_m[i], a.ranges_m[i]) << "beam " << i;
      }
      ASSERT_NEAR(AngleDifferenceRad(BeamHeadingRad(pose_b, b, i), BeamHeadingRad(pose_a, a, i)), 0.0, 1e-6)
          << "beam " << i;
    }
  }
}

TEST(RawlogTest, ActionsAndSensoryFramesRoundTrip) {
  const testing::TempDir dir;
  for (std::size_t beams : {181u, 180u, 360u}) {
    SCOPED_TRACE(std::to_string(beams) + " beams");
    const Sequence written = SyntheticSequence(40, beams, 7);
    const RawlogSummary summary = WriteRawlog(RobotLogOf(written), dir / "s.rawlog");
    EXPECT_EQ(summary.actions, 40u);
    EXPECT_EQ(summary.sensory_frames, 40u);
    const RawlogContents contents = ReadRawlogContents(dir / "s.rawlog");
    EXPECT_EQ(contents.summary.actions, 40u);
    EXPECT_EQ(contents.summary.sensory_frames, 40u);
    EXPECT_EQ(contents.summary.observations, 0u);
    EXPECT_TRUE(contents.sequence.warnings.empty());
    EXPECT_EQ(contents.sequence.name, "s");
    ExpectSameSequence(written, contents.sequence);
  }
}

TEST(RawlogTest, ObservationsFormRoundTrip) {
  const testing::TempDir dir;
  const Sequence written = SyntheticSequence(25, 361, 11);
  RawlogWriteOptions options;
  options.form = RawlogForm::kObservations;
  EXPECT_EQ(WriteRawlog(RobotLogOf(written), dir / "o.rawlog", options).observations, 50u);
  const RawlogContents contents = ReadRawlogContents(dir / "o.rawlog");
  EXPECT_EQ(contents.summary.actions, 0u);
  EXPECT_EQ(contents.summary.observations, 50u);
  ExpectSameSequence(written, contents.sequence);
}

TEST(RawlogTest, MrptReadsWhatWasWrittenAsActionSensoryFramePairs) {
  // MRPT's own CRawlog, not our reader, checks the layout and the odometry increments.
  const testing::TempDir dir;
  const Sequence written = SyntheticSequence(30, 181, 3);
  WriteRawlog(RobotLogOf(written), dir / "m.rawlog");
  mrpt::obs::CRawlog rawlog;
  ASSERT_TRUE(rawlog.loadFromRawLogFile((dir / "m.rawlog").string()));
  ASSERT_EQ(rawlog.size(), 60u);
  const std::vector<Pose>& odometry = written.odometry.poses();
  for (std::size_t i = 0; i < 30; ++i) {
    ASSERT_EQ(rawlog.getType(2 * i), mrpt::obs::CRawlog::etActionCollection);
    ASSERT_EQ(rawlog.getType(2 * i + 1), mrpt::obs::CRawlog::etSensoryFrame);
    const auto movement = rawlog.getAsAction(2 * i)->getBestMovementEstimation();
    ASSERT_TRUE(movement);
    const mrpt::poses::CPose2D mean = movement->poseChange->getMeanVal();
    const Pose expected = i == 0 ? odometry[0] : Relative(odometry[i - 1], odometry[i]);
    EXPECT_NEAR(mean.x(), expected.position.x(), 1e-9);
    EXPECT_NEAR(mean.y(), expected.position.y(), 1e-9);
    EXPECT_NEAR(AngleDifferenceRad(mean.phi(), expected.Yaw()), 0.0, 1e-9);
    const auto scan = rawlog.getAsObservations(2 * i + 1)->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
    ASSERT_TRUE(scan);
    EXPECT_EQ(scan->sensorLabel, "LASER");
    EXPECT_NEAR(mrpt::Clock::toDouble(scan->timestamp), written.scans[i].stamp_s, 1e-6);
    EXPECT_TRUE(scan->rightToLeft);
    EXPECT_NEAR(scan->aperture, std::numbers::pi, 1e-6);
    EXPECT_FALSE(scan->getScanRangeValidity(3));  // 81.91 m > 80.99 m
    EXPECT_TRUE(scan->getScanRangeValidity(2));
  }
}

TEST(RawlogTest, MrptProjectsEveryBeamWhereTheLaserScanPutsIt) {
  // MRPT's own beam model (getScanAngle + sensorPose) against LaserScan's, for CARMEN's asymmetric
  // 180-beam fan (-90..+89 deg), a symmetric one, and a clockwise scan with a turned sensor.
  const testing::TempDir dir;
  Sequence sequence = SyntheticSequence(3, 180, 5);
  const double stamp_s = sequence.scans[1].stamp_s;
  sequence.scans[1] = SyntheticSequence(3, 361, 5).scans[1];
  sequence.scans[1].stamp_s = stamp_s;
  sequence.scans[2].angle_min_rad = 1.2;
  sequence.scans[2].angle_increment_rad = -0.01;
  sequence.scans[2].sensor_pose_on_robot = Pose::Planar(-0.1, 0.05, 0.7);
  WriteRawlog(RobotLogOf(sequence), dir / "g.rawlog");
  mrpt::obs::CRawlog rawlog;
  ASSERT_TRUE(rawlog.loadFromRawLogFile((dir / "g.rawlog").string()));
  for (std::size_t s = 0; s < 3; ++s) {
    const LaserScan& scan = sequence.scans[s];
    const auto observation =
        rawlog.getAsObservations(2 * s + 1)->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
    ASSERT_EQ(observation->getScanSize(), scan.BeamCount());
    for (std::size_t i = 0; i < scan.BeamCount(); ++i) {
      const double angle = observation->getScanAngle(i);
      double x = 0, y = 0, z = 0;
      observation->sensorPose.composePoint(2.0 * std::cos(angle), 2.0 * std::sin(angle), 0.0, x, y, z);
      const Eigen::Vector3d expected =
          scan.sensor_pose_on_robot.ToIsometry() *
          Eigen::Vector3d(2.0 * std::cos(scan.BeamAngleRad(i)), 2.0 * std::sin(scan.BeamAngleRad(i)), 0.0);
      ASSERT_NEAR((Eigen::Vector3d(x, y, z) - expected).norm(), 0.0, 1e-5) << "scan " << s << " beam " << i;
    }
  }
}

TEST(RawlogTest, IntelCarmenLogRoundTrips) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  const Sequence intel = ReadCarmenSequence(log);
  const testing::TempDir dir;
  WriteRawlog(RobotLogOf(intel), dir / "intel.rawlog");
  const Sequence read = ReadRawlog(dir / "intel.rawlog");
  ExpectSameSequence(intel, read);
}

TEST(RawlogTest, ReadsMrptsSampleRawlog) {
  if (!std::filesystem::exists(kMrptSample))
    SLAMSWEEP_SKIP_OR_FAIL_IN_CI("MRPT sample rawlog not installed (Debian: mrpt-common)");
  // Count with MRPT's own CRawlog: every CSensoryFrame holds one 2D scan in this file.
  mrpt::obs::CRawlog rawlog;
  ASSERT_TRUE(rawlog.loadFromRawLogFile(kMrptSample));
  std::size_t frames = 0;
  std::size_t actions = 0;
  std::size_t scans = 0;
  for (std::size_t i = 0; i < rawlog.size(); ++i) {
    if (rawlog.getType(i) == mrpt::obs::CRawlog::etActionCollection) ++actions;
    if (rawlog.getType(i) != mrpt::obs::CRawlog::etSensoryFrame) continue;
    ++frames;
    for (const auto& observation : *rawlog.getAsObservations(i)) {
      if (std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(observation)) ++scans;
    }
  }
  ASSERT_GT(scans, 100u);
  const RawlogContents contents = ReadRawlogContents(kMrptSample);
  EXPECT_EQ(contents.sequence.scans.size(), scans);
  EXPECT_EQ(contents.summary.sensory_frames, frames);
  EXPECT_EQ(contents.summary.actions, actions);
  EXPECT_NO_THROW(ValidateSequence(contents.sequence));
  // A SICK in 0.5 deg mode: 361 beams over 180 deg.
  EXPECT_EQ(contents.sequence.scans[0].BeamCount(), 361u);
  EXPECT_NEAR(contents.sequence.scans[0].angle_increment_rad, std::numbers::pi / 360, 1e-6);
  // The file's clock (January 2006) is kept.
  EXPECT_GT(contents.sequence.scans[0].stamp_s, 1137800000.0);
  EXPECT_LT(contents.sequence.scans.back().stamp_s, 1137900000.0);
}

TEST(RawlogTest, ReadsCarmen2rawlogOutputAndRepairsItsClock) {
  if (!HaveProgram("carmen2rawlog")) SLAMSWEEP_SKIP_OR_FAIL_IN_CI("carmen2rawlog not installed (Debian: mrpt-apps)");
  const testing::TempDir dir;
  // Three FLASER records; carmen2rawlog turns each into CObservationOdometry (odom pose) + a scan.
  std::string log;
  for (int i = 0; i < 3; ++i) {
    log += "FLASER 5 1 2 3 4 5 " + std::to_string(i) + " 0 0 " + std::to_string(i) + ".5 0.25 0.1 " +
           std::to_string(10 + i) + " host " + std::to_string(10 + i) + "\n";
  }
  testing::WriteFile(dir / "in.log", log);
  const std::string command = "carmen2rawlog -q -w -i '" + (dir / "in.log").string() + "' -o '" +
                              (dir / "out.rawlog").string() + "' > '" + (dir / "c2r.txt").string() + "' 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Sequence read = ReadRawlog(dir / "out.rawlog");
  ASSERT_EQ(read.scans.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(read.odometry.poses()[i].position.x(), static_cast<double>(i) + 0.5, 1e-9);
    EXPECT_NEAR(read.odometry.poses()[i].position.y(), 0.25, 1e-9);
    EXPECT_NEAR(read.odometry.poses()[i].Yaw(), 0.1, 1e-9);
    EXPECT_EQ(read.scans[i].BeamCount(), 5u);
  }
  // carmen2rawlog gives all three the same instant: record order, with a warning naming the file.
  ASSERT_EQ(read.warnings.size(), 1u);
  EXPECT_NE(read.warnings[0].find("out.rawlog: recorded scan stamps are unusable"), std::string::npos)
      << read.warnings[0];
  EXPECT_EQ(read.scans[2].stamp_s, 2.0);
}

using slamsweep::testing::ErrorOf;

TEST(RawlogTest, UnreadableFilesAreInputErrorsNamingTheFile) {
  const testing::TempDir dir;
  EXPECT_NE(ErrorOf([&] { ReadRawlog(dir / "missing.rawlog"); }).find("missing.rawlog: cannot open"),
            std::string::npos);
  testing::WriteFile(dir / "empty.rawlog", "");
  EXPECT_NE(ErrorOf([&] { ReadRawlog(dir / "empty.rawlog"); }).find("empty.rawlog: no usable 2D laser scan"),
            std::string::npos);
  testing::WriteFile(dir / "text.rawlog", "FLASER 3 1 2 3 0 0 0 0 0 0 1 h 1\n");
  const std::string text_error = ErrorOf([&] { ReadRawlog(dir / "text.rawlog"); });
  EXPECT_NE(text_error.find("text.rawlog: object 0 cannot be read: "), std::string::npos) << text_error;
  EXPECT_EQ(text_error.find("Call stack"), std::string::npos) << text_error;

  // A rawlog cut in the middle of an object (uncompressed, so the cut lands inside the objects).
  RawlogWriteOptions options;
  options.compression_level = 0;
  WriteRawlog(RobotLogOf(SyntheticSequence(10, 181, 1)), dir / "whole.rawlog", options);
  std::ifstream in(dir / "whole.rawlog", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  testing::WriteFile(dir / "cut.rawlog", bytes.substr(0, bytes.size() / 2));
  EXPECT_NE(ErrorOf([&] { ReadRawlog(dir / "cut.rawlog"); }).find("cut.rawlog: truncated rawlog: object "),
            std::string::npos);
}

TEST(RawlogTest, ScansOfAnotherLabelAreSkippedWithAWarning) {
  const testing::TempDir dir;
  RawlogWriteOptions options;
  options.scan_label = "FRONT";
  WriteRawlog(RobotLogOf(SyntheticSequence(5, 181, 2)), dir / "f.rawlog", options);
  RawlogReadOptions read_options;
  read_options.scan_label = "REAR";
  EXPECT_NE(
      ErrorOf([&] { ReadRawlog(dir / "f.rawlog", read_options); }).find("no usable 2D laser scan labelled 'REAR'"),
      std::string::npos);
  read_options.scan_label = "FRONT";
  EXPECT_EQ(ReadRawlog(dir / "f.rawlog", read_options).scans.size(), 5u);
}

TEST(RawlogTest, WriterRejectsWhatARawlogCannotHold) {
  const testing::TempDir dir;
  Sequence one_beam = SyntheticSequence(2, 181, 1);
  one_beam.scans[1].ranges_m.resize(1);
  EXPECT_NE(ErrorOf([&] { WriteRawlog(RobotLogOf(one_beam), dir / "a.rawlog"); }).find("scan 1 has 1 beam(s)"),
            std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "a.rawlog"));

  Sequence tilted = SyntheticSequence(2, 181, 1);
  Pose pose = tilted.odometry.poses()[1];
  pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()));
  tilted.odometry.mutable_poses()[1] = pose;
  EXPECT_NE(ErrorOf([&] { WriteRawlog(RobotLogOf(tilted), dir / "b.rawlog"); }).find("odometry leaves the plane"),
            std::string::npos);

  Sequence backwards = SyntheticSequence(2, 181, 1);
  backwards.scans[1].stamp_s = backwards.scans[0].stamp_s;
  EXPECT_NE(ErrorOf([&] { WriteRawlog(RobotLogOf(backwards), dir / "c.rawlog"); }).find("does not come after"),
            std::string::npos);

  EXPECT_NE(ErrorOf([&] {
              WriteRawlog(RobotLogOf(SyntheticSequence(2, 181, 1)), dir / "no" / "such" / "d.rawlog");
            }).find("d.rawlog: cannot create the rawlog"),
            std::string::npos);

  RawlogWriteOptions options;
  options.compression_level = 10;
  EXPECT_NE(ErrorOf([&] {
              WriteRawlog(RobotLogOf(SyntheticSequence(2, 181, 1)), dir / "e.rawlog", options);
            }).find("compression_level"),
            std::string::npos);
  options = {};
  options.range_std_m = 0.0;
  EXPECT_NE(ErrorOf([&] {
              WriteRawlog(RobotLogOf(SyntheticSequence(2, 181, 1)), dir / "e.rawlog", options);
            }).find("range_std_m"),
            std::string::npos);
}

}  // namespace
}  // namespace slamsweep::evaluator
