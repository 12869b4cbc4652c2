#include "evaluator/sequence/recorded_odometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/sequence/carmen_sequence.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

/// The FLASER records of a log, in file order.
std::vector<const CarmenLaserRecord*> Flasers(const CarmenLog& log) {
  std::vector<const CarmenLaserRecord*> scans;
  for (const CarmenLaserRecord& record : log.lasers) {
    if (record.type == "FLASER") scans.push_back(&record);
  }
  return scans;
}

std::string Odom(double x, double y, double theta, double stamp_s) {
  std::ostringstream line;
  line << "ODOM " << x << ' ' << y << ' ' << theta << " 0 0 0 " << stamp_s << " pippo " << stamp_s << '\n';
  return line.str();
}

std::string FlaserLine(double x, double y, double theta, double stamp_s) {
  std::ostringstream line;
  line << "FLASER 3 1 1 1 " << x << ' ' << y << ' ' << theta << ' ' << x << ' ' << y << ' ' << theta << ' ' << stamp_s
       << " pippo " << stamp_s << '\n';
  return line.str();
}

/// A corrected log written by hand the way a corrected log's logger writes it, for a robot whose
/// wheels report 1 m forward per reading while the corrected path (the keyframes) says it went
/// 0.9 m and turned: the rebuilt odometry must be the straight wheel path, not the corrected one.
///   raw run: odometry x = 0, 1, 2, 3, 4 at t = 0..4 (keyframes at the readings t = 1 and t = 3).
///   keyframe 1 corrected at (0.9, 0, 0.1); keyframe 2 corrected at (2.7, 0.2, 0.3).
/// Each reading is the last keyframe's corrected pose composed with the raw increment since it; each
/// keyframe is followed by a reset ODOM repeating its pose (stamp 0, as most of intel's are).
std::string HandMadeCorrectedLog() {
  const Pose k1 = Pose::Planar(0.9, 0.0, 0.1);
  const Pose k2 = Pose::Planar(2.7, 0.2, 0.3);
  std::string text;
  text += Odom(0, 0, 0, 0.0);
  text += Odom(1, 0, 0, 1.0);
  text += FlaserLine(0.9, 0.0, 0.1, 1.0);
  text += Odom(0.9, 0.0, 0.1, 0.0);  // reset
  const Pose r2 = k1 * Pose::Planar(1.0, 0.0, 0.0);
  text += Odom(r2.position.x(), r2.position.y(), r2.Yaw(), 2.0);
  const Pose r3 = k1 * Pose::Planar(2.0, 0.0, 0.0);
  text += Odom(r3.position.x(), r3.position.y(), r3.Yaw(), 3.0);
  text += FlaserLine(2.7, 0.2, 0.3, 3.0);
  text += Odom(2.7, 0.2, 0.3, 1.13);  // reset with an ordinary-looking, out-of-order stamp
  const Pose r4 = k2 * Pose::Planar(1.0, 0.0, 0.0);
  text += Odom(r4.position.x(), r4.position.y(), r4.Yaw(), 4.0);
  return text;
}

TEST(RecordedOdometryTest, HandMadeLogGivesTheWheelPathResetsByPoseNotStamp) {
  const CarmenLog log = ParseCarmenLog(HandMadeCorrectedLog(), "hand.log");
  const std::vector<const CarmenLaserRecord*> scans = Flasers(log);
  const RecordedOdometry odometry = RebuildRecordedOdometry(log, scans, "hand.log", {});
  EXPECT_EQ(odometry.resets, 2u);
  ASSERT_EQ(odometry.readings.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    const Pose& pose = odometry.readings.poses()[i];
    EXPECT_NEAR(pose.position.x(), static_cast<double>(i), 1e-5) << "reading " << i;
    EXPECT_NEAR(pose.position.y(), 0.0, 1e-5) << "reading " << i;
    EXPECT_NEAR(pose.Yaw(), 0.0, 1e-5) << "reading " << i;
    EXPECT_EQ(odometry.readings.stamps_s()[i], static_cast<double>(i));
  }
  EXPECT_EQ(odometry.scan_readings, (std::vector<std::size_t>{1, 3}));
  EXPECT_EQ(odometry.repaired_stamps, 0u);
}

TEST(RecordedOdometryTest, RecordedModeFeedsTheWheelOdometryAndKeepsTheCorrectedReference) {
  CarmenSequenceOptions options;
  options.odometry = OdometryMode::kRecorded;
  const Sequence sequence =
      CarmenLogToSequence(ParseCarmenLog(HandMadeCorrectedLog(), "hand.log"), "hand.log", options);
  ASSERT_EQ(sequence.odometry.size(), 2u);
  EXPECT_NEAR(sequence.odometry.poses()[0].position.x(), 1.0, 1e-5);
  EXPECT_NEAR(sequence.odometry.poses()[1].position.x(), 3.0, 1e-5);
  EXPECT_NEAR(sequence.odometry.poses()[1].Yaw(), 0.0, 1e-5);
  ASSERT_TRUE(sequence.reference.has_value());
  EXPECT_NEAR(sequence.reference->poses()[1].position.x(), 2.7, 1e-9);
  EXPECT_EQ(sequence.odometry_readings.size(), 5u);
  EXPECT_FALSE(OdometryEqualsReference(sequence));
  EXPECT_NO_THROW(ValidateSequence(sequence));

  options.odometry = OdometryMode::kReference;
  const Sequence reference =
      CarmenLogToSequence(ParseCarmenLog(HandMadeCorrectedLog(), "hand.log"), "hand.log", options);
  EXPECT_TRUE(OdometryEqualsReference(reference));
  EXPECT_TRUE(reference.odometry_readings.empty());
}

TEST(RecordedOdometryTest, LogWithoutAStreamIsAnErrorNamingTheLine) {
  // A scan without any reading before it: no stream.
  const std::string text = FlaserLine(0, 0, 0, 1.0) + FlaserLine(1, 0, 0, 2.0);
  const CarmenLog log = ParseCarmenLog(text, "bare.log");
  try {
    RebuildRecordedOdometry(log, Flasers(log), "bare.log", {});
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("bare.log:1"), std::string::npos) << error.what();
  }
  // An ODOM right after a scan that does not repeat its pose: not a corrected log's reset.
  const std::string moved =
      Odom(0, 0, 0, 0.5) + FlaserLine(0, 0, 0, 1.0) + Odom(5, 0, 0, 1.5) + FlaserLine(1, 0, 0, 2.0);
  const CarmenLog moved_log = ParseCarmenLog(moved, "moved.log");
  try {
    RebuildRecordedOdometry(moved_log, Flasers(moved_log), "moved.log", {});
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("moved.log:3"), std::string::npos) << error.what();
  }
  CarmenSequenceOptions options;
  options.odometry = OdometryMode::kRecorded;
  options.require_recorded_odometry = true;
  EXPECT_THROW(CarmenLogToSequence(log, "bare.log", options), InputError);
  options.require_recorded_odometry = false;
  const Sequence fallback = CarmenLogToSequence(log, "bare.log", options);
  EXPECT_TRUE(OdometryEqualsReference(fallback));
  EXPECT_FALSE(fallback.warnings.empty());
}

/// Counts of the Radish logs' ODOM streams, measured independently when the data was taken
/// (PROVENANCE.txt; the issue that asked for the recorded odometry).
struct StreamFacts {
  const char* file;
  std::size_t odom_lines;
  std::size_t readings;
  std::size_t resets;
};

void ExpectStream(const std::filesystem::path& path, const StreamFacts& facts, RecordedOdometry& out) {
  const CarmenLog log = ReadCarmenLog(path);
  EXPECT_EQ(log.odometry.size(), facts.odom_lines);
  const std::vector<const CarmenLaserRecord*> scans = Flasers(log);
  out = RebuildRecordedOdometry(log, scans, path, {});
  EXPECT_EQ(out.readings.size(), facts.readings);
  EXPECT_EQ(out.resets, facts.resets);
  EXPECT_EQ(out.resets, scans.size()) << "one reset after every keyframe";
}

TEST(RecordedOdometryTest, IntelStreamCountsQuantumAndDrift) {
  SLAMSWEEP_REQUIRE_SHARED(path, "datasets/intel/intel-corrected.log.gz");
  RecordedOdometry odometry;
  ExpectStream(path, {"intel", 14541, 13631, 910}, odometry);
  // Stamps are not monotonic: repeats and steps back are repaired, and said.
  EXPECT_EQ(odometry.stamp_outcome, StampOutcome::kRepaired);
  EXPECT_GT(odometry.repaired_stamps, 2459u);
  ASSERT_FALSE(odometry.warnings.empty());
  EXPECT_NE(odometry.warnings[0].find("step back"), std::string::npos);

  // The encoders' quantum: rotation steps are whole multiples of 0.0061455 rad.
  constexpr double kQuantumRad = 0.0061455;
  std::size_t turning = 0;
  std::size_t on_quantum = 0;
  for (std::size_t i = 1; i < odometry.readings.size(); ++i) {
    const double step = Relative(odometry.readings.poses()[i - 1], odometry.readings.poses()[i]).Yaw();
    if (std::abs(step) < 1e-9) continue;
    ++turning;
    const double multiple = step / kQuantumRad;
    if (std::abs(multiple - std::round(multiple)) < 0.02) ++on_quantum;
  }
  ASSERT_GT(turning, 1000u);
  EXPECT_GT(static_cast<double>(on_quantum) / static_cast<double>(turning), 0.99);

  // It is the robot's odometry, not the corrected path: far from it at the end.
  CarmenSequenceOptions options;
  options.odometry = OdometryMode::kRecorded;
  const Sequence sequence = ReadCarmenSequence(path, options);
  ASSERT_TRUE(sequence.reference.has_value());
  ASSERT_EQ(sequence.odometry.size(), 910u);
  double sum_m = 0.0;
  for (std::size_t i = 0; i < sequence.odometry.size(); ++i) {
    sum_m += (sequence.odometry.poses()[i].position - sequence.reference->poses()[i].position).norm();
  }
  const double end_m = (sequence.odometry.poses().back().position - sequence.reference->poses().back().position).norm();
  EXPECT_GT(sum_m / 910.0, 10.0);
  EXPECT_GT(end_m, 30.0);
  EXPECT_FALSE(OdometryEqualsReference(sequence));
  EXPECT_EQ(sequence.odometry_readings.size(), 13631u);
  EXPECT_NO_THROW(ValidateSequence(sequence));
}

TEST(RecordedOdometryTest, Fr079StreamCounts) {
  SLAMSWEEP_REQUIRE_SHARED(path, "datasets/fr079/freiburg-079-corrected.log.gz");
  RecordedOdometry odometry;
  ExpectStream(path, {"fr079", 4934 + 4791, 4934, 4791}, odometry);
}

TEST(RecordedOdometryTest, CsailStreamCountsAndNoUsableClock) {
  SLAMSWEEP_REQUIRE_SHARED(path, "datasets/mit-csail/csail-corrected.log.gz");
  RecordedOdometry odometry;
  ExpectStream(path, {"csail", 1988 + 406, 1988, 406}, odometry);
  // Every stamp prints as 1.13486e+09: stamped in record order, and said.
  EXPECT_EQ(odometry.stamp_outcome, StampOutcome::kRecordOrder);
  ASSERT_FALSE(odometry.warnings.empty());
  EXPECT_NE(odometry.warnings[0].find("record order"), std::string::npos);
}

}  // namespace
}  // namespace slamsweep::evaluator
