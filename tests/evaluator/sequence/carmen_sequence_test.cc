#include "evaluator/sequence/carmen_sequence.h"

#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>

#include "evaluator/core/input_error.h"
#include "tests/support/shared_data.h"
#include "tests/support/input_error_text.h"

namespace slamsweep::evaluator {
namespace {

/// A FLASER line with `beams` readings of `range_m` (the first one `first_range_m`).
std::string Flaser(std::size_t beams, double first_range_m, double range_m, const std::string& pose,
                   const std::string& odom, double stamp_s) {
  std::ostringstream line;
  line << "FLASER " << beams << ' ' << first_range_m;
  for (std::size_t i = 1; i < beams; ++i) line << ' ' << range_m;
  line << ' ' << pose << ' ' << odom << ' ' << stamp_s << " pippo " << stamp_s << '\n';
  return line.str();
}

Sequence FromText(const std::string& text, const CarmenSequenceOptions& options = {}) {
  return CarmenLogToSequence(ParseCarmenLog(text, "mem.log"), "mem.log", options);
}

bool AnyWarningContains(const Sequence& sequence, const std::string& needle) {
  for (const std::string& warning : sequence.warnings) {
    if (warning.find(needle) != std::string::npos) return true;
  }
  return false;
}

using slamsweep::testing::ErrorOf;

TEST(CarmenSequenceTest, FlaserRecordsBecomeScansOdometryAndReference) {
  const std::string text =
      "PARAM robot_front_laser_max 50.5 nohost 0\n"
      "ODOM 0 0 0 0 0 0 0.5 pippo 0.5\n" +
      Flaser(181, 1.25, 2.5, "1 2 0.5", "1.1 2.1 0.6", 10.0) +
      Flaser(181, 3.0, 81.91, "1.5 2 0.5", "1.6 2.1 0.6", 10.5);
  const Sequence sequence = FromText(text);
  EXPECT_EQ(sequence.name, "mem");
  ASSERT_EQ(sequence.scans.size(), 2u);
  const LaserScan& scan = sequence.scans[0];
  EXPECT_EQ(scan.stamp_s, 10.0);
  EXPECT_EQ(scan.BeamCount(), 181u);
  EXPECT_EQ(scan.ranges_m[0], 1.25f);
  EXPECT_DOUBLE_EQ(scan.angle_min_rad, -std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(scan.angle_increment_rad, std::numbers::pi / 180);
  EXPECT_EQ(scan.range_max_m, 50.5);
  EXPECT_EQ(scan.range_min_m, 0.0);
  EXPECT_TRUE(scan.sensor_pose_on_robot.position.isZero());
  EXPECT_TRUE(scan.IsHit(scan.ranges_m[1]));
  EXPECT_FALSE(sequence.scans[1].IsHit(sequence.scans[1].ranges_m[1]));  // 81.91: the SICK "no return" code

  ASSERT_EQ(sequence.odometry.size(), 2u);
  EXPECT_EQ(sequence.odometry.stamps_s()[1], 10.5);
  EXPECT_DOUBLE_EQ(sequence.odometry.poses()[1].position.x(), 1.6);
  EXPECT_DOUBLE_EQ(sequence.odometry.poses()[1].Yaw(), 0.6);
  ASSERT_TRUE(sequence.reference.has_value());
  EXPECT_DOUBLE_EQ(sequence.reference->poses()[1].position.x(), 1.5);
  EXPECT_DOUBLE_EQ(sequence.reference->poses()[1].Yaw(), 0.5);
  EXPECT_EQ(sequence.reference->stamps_s(), sequence.odometry.stamps_s());
  EXPECT_TRUE(sequence.warnings.empty());
  EXPECT_EQ(sequence.provenance.source, "mem.log");
  EXPECT_NO_THROW(ValidateSequence(sequence));
}

TEST(CarmenSequenceTest, MaxRangeComesFromTheOptionThenTheLogThenTheDefault) {
  const std::string scans = Flaser(180, 1, 1, "0 0 0", "0 0 0", 1) + Flaser(180, 1, 1, "0 0 0", "0 0 0", 2);
  EXPECT_EQ(FromText(scans).scans[0].range_max_m, 80.0);
  EXPECT_EQ(FromText("PARAM robot_front_laser_max 50 nohost 0\n" + scans).scans[0].range_max_m, 50.0);
  CarmenSequenceOptions options;
  options.max_range_m = 30.0;
  EXPECT_EQ(FromText("PARAM robot_front_laser_max 50 nohost 0\n" + scans, options).scans[0].range_max_m, 30.0);
  options = {};
  options.default_max_range_m = 20.0;
  EXPECT_EQ(FromText(scans, options).scans[0].range_max_m, 20.0);
}

TEST(CarmenSequenceTest, ConflictingMaxRangeParamsWarnAndTheLastWins) {
  const std::string text = "PARAM robot_front_laser_max 50 nohost 0\nPARAM robot_front_laser_max 60 nohost 0\n" +
                           Flaser(180, 1, 1, "0 0 0", "0 0 0", 1);
  const Sequence sequence = FromText(text);
  EXPECT_EQ(sequence.scans[0].range_max_m, 60.0);
  EXPECT_TRUE(AnyWarningContains(sequence, "mem.log:2: PARAM robot_front_laser_max = 60 replaces 50"));
}

TEST(CarmenSequenceTest, ConstantStampsAreReplacedByRecordOrderWithAWarningNamingTheFile) {
  std::string text;
  for (int i = 0; i < 4; ++i) text += Flaser(181, 1, 1, std::to_string(i) + " 0 0", std::to_string(i) + " 0 0", 0.0);
  const Sequence sequence = FromText(text);
  ASSERT_EQ(sequence.scans.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(sequence.scans[i].stamp_s, static_cast<double>(i));
    EXPECT_EQ(sequence.odometry.stamps_s()[i], static_cast<double>(i));
    EXPECT_EQ(sequence.reference->stamps_s()[i], static_cast<double>(i));
  }
  ASSERT_EQ(sequence.warnings.size(), 1u);
  EXPECT_NE(sequence.warnings[0].find("mem.log: "), std::string::npos) << sequence.warnings[0];
  EXPECT_NE(sequence.warnings[0].find("record order"), std::string::npos) << sequence.warnings[0];
  EXPECT_NE(sequence.warnings[0].find("first on line 2"), std::string::npos) << sequence.warnings[0];
}

TEST(CarmenSequenceTest, AFewBackwardStampsAreRepairedAndTheirLinesNamed) {
  std::string text;
  for (int i = 0; i < 150; ++i) {
    const double stamp_s = i == 100 ? 98.5 : static_cast<double>(i);
    text += Flaser(180, 1, 1, "0 0 0", "0 0 0", stamp_s);
  }
  const Sequence sequence = FromText(text);
  EXPECT_EQ(sequence.scans[99].stamp_s, 99.0);
  EXPECT_DOUBLE_EQ(sequence.scans[100].stamp_s, 99.001);
  EXPECT_EQ(sequence.scans[101].stamp_s, 101.0);
  ASSERT_EQ(sequence.warnings.size(), 1u);
  EXPECT_NE(sequence.warnings[0].find("lines 101"), std::string::npos) << sequence.warnings[0];
  EXPECT_NO_THROW(ValidateSequence(sequence));
}

TEST(CarmenSequenceTest, RecordedPolicyRejectsABackwardStampAtItsLine) {
  CarmenSequenceOptions options;
  options.stamps.policy = StampPolicy::kRecorded;
  const std::string text = Flaser(180, 1, 1, "0 0 0", "0 0 0", 2.0) + Flaser(180, 1, 1, "0 0 0", "0 0 0", 1.0);
  EXPECT_NE(ErrorOf([&] { FromText(text, options); }).find("mem.log:2: ipc_timestamp 1 does not come after"),
            std::string::npos);
}

TEST(CarmenSequenceTest, RobotLaserRecordsWinAndStateTheirGeometry) {
  // start -1.5 rad, 0.01 rad steps, max 30 m; laser 0.2 m ahead of the robot at heading 0.3.
  const double x = 1.0 + 0.2 * std::cos(0.3);
  const double y = 2.0 + 0.2 * std::sin(0.3);
  std::ostringstream robot;
  robot.precision(17);
  robot << "ROBOTLASER1 0 -1.5 3.0 0.01 30 0.01 0 3 1 2 31 0 " << x << ' ' << y
        << " 0.3 1 2 0.3 0 0 0 0 0 7.5 b21 7.5\n";
  const std::string text = Flaser(180, 1, 1, "0 0 0", "0 0 0", 7.5) + robot.str() + "RLASER 2 1 1 0 0 0 0 0 0 7 h 7\n";
  const Sequence sequence = FromText(text);
  ASSERT_EQ(sequence.scans.size(), 1u);
  const LaserScan& scan = sequence.scans[0];
  EXPECT_EQ(scan.BeamCount(), 3u);
  EXPECT_EQ(scan.angle_min_rad, -1.5);
  EXPECT_EQ(scan.angle_increment_rad, 0.01);
  EXPECT_EQ(scan.range_max_m, 30.0);
  EXPECT_FALSE(scan.IsHit(scan.ranges_m[2]));  // 31 m beyond the stated 30 m
  EXPECT_NEAR(scan.sensor_pose_on_robot.position.x(), 0.2, 1e-12);
  EXPECT_NEAR(scan.sensor_pose_on_robot.position.y(), 0.0, 1e-12);
  EXPECT_NEAR(scan.sensor_pose_on_robot.Yaw(), 0.0, 1e-12);
  EXPECT_TRUE(AnyWarningContains(sequence, "1 FLASER records ignored"));
  EXPECT_TRUE(AnyWarningContains(sequence, "1 RLASER records ignored"));
}

/// An RLASER line: like Flaser, for the rear laser.
std::string Rlaser(std::size_t beams, double first_range_m, double range_m, const std::string& pose,
                   const std::string& odom, double stamp_s) {
  std::string line = Flaser(beams, first_range_m, range_m, pose, odom, stamp_s);
  return "RLASER" + line.substr(std::string("FLASER").size());
}

TEST(CarmenSequenceTest, FrontLaserIsTheDefaultAndRearLaserIsAnOption) {
  const std::string text = Flaser(181, 1, 1, "0 0 0", "0 0 0", 1.0) + Rlaser(181, 2, 2, "0 0 0", "0 0 0", 1.05) +
                           Flaser(181, 1, 1, "0.1 0 0", "0.1 0 0", 1.1) +
                           Rlaser(181, 2, 2, "0.1 0 0", "0.1 0 0", 1.15) +
                           Rlaser(181, 2, 2, "0.2 0 0", "0.2 0 0", 1.25);
  const Sequence front = FromText(text);
  ASSERT_EQ(front.scans.size(), 2u);
  EXPECT_EQ(front.scans[1].stamp_s, 1.1);
  EXPECT_EQ(front.scans[0].ranges_m[0], 1.0f);
  EXPECT_NEAR(front.scans[0].sensor_pose_on_robot.Yaw(), 0.0, 1e-12);
  EXPECT_TRUE(AnyWarningContains(front, "3 RLASER records ignored")) << ::testing::PrintToString(front.warnings);

  CarmenSequenceOptions rear_options;
  rear_options.use_rear_laser = true;
  const Sequence rear = FromText(text, rear_options);
  ASSERT_EQ(rear.scans.size(), 3u);
  EXPECT_EQ(rear.scans[2].stamp_s, 1.25);
  EXPECT_EQ(rear.scans[0].ranges_m[0], 2.0f);
  EXPECT_EQ(rear.odometry.size(), 3u);
  ASSERT_TRUE(rear.reference.has_value());
  EXPECT_NEAR(rear.reference->poses()[2].position.x(), 0.2, 1e-12);
  EXPECT_TRUE(AnyWarningContains(rear, "2 FLASER records ignored")) << ::testing::PrintToString(rear.warnings);

  EXPECT_NE(
      ErrorOf([&] { FromText(Flaser(181, 1, 1, "0 0 0", "0 0 0", 1.0), rear_options); }).find("no RLASER records"),
      std::string::npos);
}

TEST(CarmenSequenceTest, RearLaserBeamsPointBackwards) {
  // 181 beams from -90 to +90 deg about the sensor axis; the sensor faces backwards (yaw pi), so on
  // the robot the first beam points to -90 + 180 = +90 deg (left), the middle one straight back, the
  // last one to +270 = -90 deg (right). The robot at (1, 2) heading 90 deg: "back" is world -y.
  CarmenSequenceOptions options;
  options.use_rear_laser = true;
  const Sequence sequence =
      FromText(Rlaser(181, 2, 2, "1 2 1.5707963267948966", "1 2 1.5707963267948966", 1.0), options);
  ASSERT_EQ(sequence.scans.size(), 1u);
  const LaserScan& scan = sequence.scans[0];
  EXPECT_NEAR(std::abs(scan.sensor_pose_on_robot.Yaw()), std::numbers::pi, 1e-12);
  EXPECT_NEAR(scan.sensor_pose_on_robot.position.norm(), 0.0, 1e-12);
  const Pose sensor_in_world = sequence.reference->poses()[0] * scan.sensor_pose_on_robot;
  const auto end_point = [&](std::size_t beam) {
    const double angle = scan.angle_min_rad + static_cast<double>(beam) * scan.angle_increment_rad;
    const Eigen::Vector3d in_sensor(2.0 * std::cos(angle), 2.0 * std::sin(angle), 0.0);
    return Eigen::Vector3d(sensor_in_world.position + sensor_in_world.orientation * in_sensor);
  };
  // Middle beam: straight behind the robot, world (1, 0).
  EXPECT_NEAR(end_point(90).x(), 1.0, 1e-9);
  EXPECT_NEAR(end_point(90).y(), 0.0, 1e-9);
  // First beam: to the robot's left; the robot faces +y, so its left is -x: world (-1, 2).
  EXPECT_NEAR(end_point(0).x(), -1.0, 1e-9);
  EXPECT_NEAR(end_point(0).y(), 2.0, 1e-9);
  // Last beam: to the robot's right, world (3, 2).
  EXPECT_NEAR(end_point(180).x(), 3.0, 1e-9);
  EXPECT_NEAR(end_point(180).y(), 2.0, 1e-9);
}

TEST(CarmenSequenceTest, RearLaserMaxRangeComesFromItsOwnParam) {
  CarmenSequenceOptions options;
  options.use_rear_laser = true;
  const std::string text = "PARAM robot_front_laser_max 50 nohost 0\nPARAM robot_rear_laser_max 20 nohost 0\n" +
                           Rlaser(181, 2, 2, "0 0 0", "0 0 0", 1.0);
  EXPECT_EQ(FromText(text, options).scans[0].range_max_m, 20.0);
  EXPECT_EQ(FromText("PARAM robot_front_laser_max 50 nohost 0\n" + Rlaser(181, 2, 2, "0 0 0", "0 0 0", 1.0), options)
                .scans[0]
                .range_max_m,
            80.0);
}

TEST(CarmenSequenceTest, UnknownBeamCountIsSpreadAsCarmenDoesWithAWarning) {
  const Sequence sequence = FromText(Flaser(91, 1, 1, "0 0 0", "0 0 0", 1.0));
  EXPECT_DOUBLE_EQ(sequence.scans[0].angle_increment_rad, std::numbers::pi / 90);
  ASSERT_EQ(sequence.warnings.size(), 1u);
  EXPECT_NE(sequence.warnings[0].find("(lines 1)"), std::string::npos) << sequence.warnings[0];
}

TEST(CarmenSequenceTest, RawLogsHaveNoReference) {
  CarmenSequenceOptions options;
  options.logged_pose_is_reference = false;
  EXPECT_FALSE(FromText(Flaser(180, 1, 1, "0 0 0", "0 0 0", 1.0), options).reference.has_value());
}

TEST(CarmenSequenceTest, RelationsAreReadAndShiftedOntoTheLogClock) {
  const testing::TempDir dir;
  const auto relations = testing::WriteFile(dir / "x.relations", "1000.5 1001.5 1 0 0 0 0 0.1\n");
  CarmenSequenceOptions options;
  options.relations_path = relations;
  options.relations_offset_s = -1000.0;
  const Sequence sequence =
      FromText(Flaser(180, 1, 1, "0 0 0", "0 0 0", 0.0) + Flaser(180, 1, 1, "0 0 0", "0 0 0", 2.0), options);
  ASSERT_TRUE(sequence.relations.has_value());
  ASSERT_EQ(sequence.relations->size(), 1u);
  EXPECT_DOUBLE_EQ(sequence.relations->front().t1_s, 0.5);
  EXPECT_DOUBLE_EQ(sequence.relations->front().t2_s, 1.5);
  EXPECT_EQ(sequence.relations_outside_log, 0u);
}

// A log of part of a run holds only the relations whose two stamps lie inside its span; the others are
// counted, never scored (and never counted as missed by a program).
TEST(CarmenSequenceTest, RelationsOutsideTheLogsSpanAreCountedAndLeftOut) {
  const testing::TempDir dir;
  const auto relations = testing::WriteFile(dir / "x.relations",
                                            "0.5 1.5 1 0 0 0 0 0\n"     // inside
                                            "1.5 2.5 1 0 0 0 0 0\n"     // ends after the last scan
                                            "-0.5 1.0 1 0 0 0 0 0\n");  // starts before the first
  CarmenSequenceOptions options;
  options.relations_path = relations;
  const Sequence sequence =
      FromText(Flaser(180, 1, 1, "0 0 0", "0 0 0", 0.0) + Flaser(180, 1, 1, "0 0 0", "0 0 0", 2.0), options);
  ASSERT_TRUE(sequence.relations.has_value());
  ASSERT_EQ(sequence.relations->size(), 1u);
  EXPECT_DOUBLE_EQ(sequence.relations->front().t1_s, 0.5);
  EXPECT_EQ(sequence.relations_outside_log, 2u);
}

TEST(CarmenSequenceTest, ARelationsWindowKeepsOnlyTheRelationsInsideIt) {
  const testing::TempDir dir;
  const auto relations = testing::WriteFile(dir / "x.relations", "100.5 101.5 1 0 0 0 0 0\n100.2 103 1 0 0 0 0 0\n");
  CarmenSequenceOptions options;
  options.relations_path = relations;
  options.relations_offset_s = -100.0;
  options.relations_window_s = std::array<double, 2>{100.0, 102.0};  // the relations' own clock
  std::string text;
  for (int i = 0; i < 5; ++i) text += Flaser(180, 1, 1, "0 0 0", "0 0 0", i);
  const Sequence sequence = FromText(text, options);
  ASSERT_TRUE(sequence.relations.has_value());
  ASSERT_EQ(sequence.relations->size(), 1u);
  EXPECT_DOUBLE_EQ(sequence.relations->front().t1_s, 0.5);
  EXPECT_EQ(sequence.relations_outside_log, 1u);
}

/// A raw log of `count` scans 0.2 s apart moving 0.1 m each along x, whose record `late` is stamped
/// `delay_s` late; scan i's first range is 1 + i / 100, so scans can be told apart.
std::string RawLogWithALateStamp(int count, int late, double delay_s) {
  std::string text;
  for (int i = 0; i < count; ++i) {
    const std::string pose = std::to_string(0.1 * i) + " 0 0";
    const double stamp_s = 0.2 * i + (i == late ? delay_s : 0.0);
    text += Flaser(180, 1.0 + i / 100.0, 2.0, pose, pose, stamp_s);
  }
  return text;
}

CarmenSequenceOptions Raw() {
  CarmenSequenceOptions options;
  options.logged_pose_is_reference = false;
  return options;
}

// A raw log: its logged pose is the robot's odometry, and there is no reference to flag it against.
TEST(CarmenSequenceTest, ARawLogsLoggedPoseIsItsOdometryAndNeverTheReference) {
  const Sequence sequence = FromText(RawLogWithALateStamp(10, -1, 0.0), Raw());
  EXPECT_FALSE(sequence.reference.has_value());
  EXPECT_FALSE(OdometryEqualsReference(sequence));
  ASSERT_EQ(sequence.odometry.size(), 10u);
  EXPECT_DOUBLE_EQ(sequence.odometry.poses()[3].position.x(), 0.3);
  ASSERT_TRUE(sequence.stamp_facts.has_value());
  EXPECT_EQ(sequence.stamp_facts->outcome, StampOutcome::kRecorded);
  EXPECT_FALSE(sequence.stamp_facts->order_check.has_value());
  EXPECT_NO_THROW(ValidateSequence(sequence));
}

// Records stay in file order; the late stamp alone moves between its neighbours (a corrected log's lift
// would crowd the next records a millisecond apart), and the facts say what was done.
TEST(CarmenSequenceTest, ARawLogKeepsFileOrderAndRetimesALateStampAlone) {
  const Sequence sequence = FromText(RawLogWithALateStamp(400, 100, 0.7), Raw());
  ASSERT_EQ(sequence.scans.size(), 400u);
  for (std::size_t i = 0; i < 400; ++i) EXPECT_FLOAT_EQ(sequence.scans[i].ranges_m[0], 1.0f + i / 100.0f) << i;
  EXPECT_NEAR(sequence.scans[100].stamp_s, 20.0, 1e-9);
  EXPECT_NEAR(sequence.scans[101].stamp_s, 20.2, 1e-9);
  EXPECT_NEAR(sequence.scans[103].stamp_s, 20.6, 1e-9);
  ASSERT_TRUE(sequence.stamp_facts.has_value());
  EXPECT_EQ(sequence.stamp_facts->outcome, StampOutcome::kRetimed);
  EXPECT_EQ(sequence.stamp_facts->steps_back, 1u);
  EXPECT_EQ(sequence.stamp_facts->duplicates, 0u);
  EXPECT_EQ(sequence.stamp_facts->changed, 1u);
  EXPECT_NEAR(sequence.stamp_facts->largest_change_s, 0.7, 1e-9);
  EXPECT_TRUE(AnyWarningContains(sequence, "re-timed")) << ::testing::PrintToString(sequence.warnings);
  EXPECT_NO_THROW(ValidateSequence(sequence));
  // The same log read as a corrected log lifts instead (today's behaviour for corrected logs).
  const Sequence corrected = FromText(RawLogWithALateStamp(400, 100, 0.7));
  EXPECT_NEAR(corrected.scans[101].stamp_s, 20.701, 1e-9);
}

TEST(CarmenSequenceTest, ARawLogCountsRepeatedStamps) {
  std::string text;
  for (int i = 0; i < 50; ++i) {
    const std::string pose = std::to_string(0.1 * i) + " 0 0";
    text += Flaser(180, 1, 1, pose, pose, i == 20 ? 0.2 * 19 : 0.2 * i);
  }
  const Sequence sequence = FromText(text, Raw());
  ASSERT_TRUE(sequence.stamp_facts.has_value());
  EXPECT_EQ(sequence.stamp_facts->duplicates, 1u);
  EXPECT_EQ(sequence.stamp_facts->steps_back, 0u);
  EXPECT_EQ(sequence.stamp_facts->changed, 1u);
  EXPECT_NEAR(sequence.scans[20].stamp_s, 4.0, 1e-9);
  EXPECT_NO_THROW(ValidateSequence(sequence));
}

// Relation stamps name scans by the stamps they were logged with: a relation at the late record's logged
// stamp follows it to its re-timed stamp.
TEST(CarmenSequenceTest, ARawLogsRelationsFollowTheScansTheyName) {
  const testing::TempDir dir;
  const auto relations = testing::WriteFile(dir / "x.relations", "10 20.7 10 0 0 0 0 0\n");
  CarmenSequenceOptions options = Raw();
  options.relations_path = relations;
  const Sequence sequence = FromText(RawLogWithALateStamp(200, 100, 0.7), options);
  ASSERT_TRUE(sequence.relations.has_value());
  ASSERT_EQ(sequence.relations->size(), 1u);
  EXPECT_NEAR(sequence.relations->front().t1_s, 10.0, 1e-9);
  EXPECT_NEAR(sequence.relations->front().t2_s, 20.0, 1e-9);
}

// Which order the records were taken in: at the backward step, the scans and odometry change less in file
// order than in the order the stamps give.
TEST(CarmenSequenceTest, TheOrderCheckFindsTheFileOrderWhereItIsTheRobots) {
  std::string text;
  for (int i = 0; i < 40; ++i) {
    const std::string pose = std::to_string(0.1 * i) + " 0 0";
    // Every tenth record's stamp comes after its successor's, as late stamps do.
    const double stamp_s = 0.2 * i + (i % 10 == 5 ? 0.3 : 0.0);
    text += Flaser(180, 1.0 + i / 10.0, 2.0 + i / 10.0, pose, pose, stamp_s);
  }
  const Sequence sequence = FromText(text, Raw());
  ASSERT_TRUE(sequence.stamp_facts.has_value());
  ASSERT_TRUE(sequence.stamp_facts->order_check.has_value());
  const RecordOrderCheck& check = *sequence.stamp_facts->order_check;
  EXPECT_EQ(check.steps, 4u);
  EXPECT_EQ(check.scans_closer_in_file_order, 4u);
  EXPECT_EQ(check.scans_closer_in_stamp_order, 0u);
  EXPECT_EQ(check.odometry_shorter_in_file_order, 4u);
  EXPECT_EQ(check.odometry_shorter_in_stamp_order, 0u);
}

TEST(CarmenSequenceTest, BadInputIsAnInputErrorThatSaysWhere) {
  EXPECT_NE(ErrorOf([] { FromText("ODOM 0 0 0 0 0 0 1 h 1\n"); }).find("mem.log: no FLASER or ROBOTLASER1"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] {
              FromText("ODOM 0 0 0 0 0 0 1 h 1\n" + Flaser(1, 1, 1, "0 0 0", "0 0 0", 1.0));
            }).find("mem.log:2: FLASER with 1 readings"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] {
              FromText("PARAM robot_front_laser_max far nohost 0\n" + Flaser(180, 1, 1, "0 0 0", "0 0 0", 1.0));
            }).find("mem.log:1: PARAM robot_front_laser_max: expected a range"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] {
              FromText("ROBOTLASER1 0 -1.5 3.0 0 30 0.01 0 2 1 2 0 0 0 0 0 0 0 0 0 0 0 0 7.5 b21 7.5\n");
            }).find("mem.log:1: ROBOTLASER1 angular_res"),
            std::string::npos);
  CarmenSequenceOptions options;
  options.min_range_m = -1.0;
  EXPECT_NE(ErrorOf([&] { FromText(Flaser(180, 1, 1, "0 0 0", "0 0 0", 1.0), options); }).find("min_range_m"),
            std::string::npos);
  options = {};
  options.max_range_m = 0.0;
  EXPECT_NE(ErrorOf([&] { FromText(Flaser(180, 1, 1, "0 0 0", "0 0 0", 1.0), options); }).find("max_range_m"),
            std::string::npos);
  EXPECT_THROW(ReadCarmenSequence("/nonexistent/slamsweep.log"), InputError);
}

// ---- the shared datasets ----

/// Scan and beam counts from the "Stats:" line of a dataset's PROVENANCE.txt (computed there by an
/// independent script: "FLASER=910 ... readings=[180]").
struct DatasetStats {
  std::size_t scans = 0;
  std::size_t beams = 0;
  bool stamps_degenerate = false;
};

DatasetStats ReadStats(const std::filesystem::path& provenance) {
  std::ifstream in(provenance);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::smatch match;
  DatasetStats stats;
  if (std::regex_search(text, match, std::regex(R"(Stats: .*FLASER=(\d+) .*readings=\[(\d+)\])"))) {
    stats.scans = std::stoul(match[1]);
    stats.beams = std::stoul(match[2]);
  }
  stats.stamps_degenerate = text.find("timestamps are degenerate") != std::string::npos;
  return stats;
}

struct DatasetCase {
  const char* folder;
  const char* log;
};

class CarmenDatasetTest : public ::testing::TestWithParam<DatasetCase> {};

TEST_P(CarmenDatasetTest, ReadsWithTheCountsOfItsProvenanceStats) {
  const DatasetCase& dataset = GetParam();
  const std::string folder = std::string("datasets/") + dataset.folder;
  SLAMSWEEP_REQUIRE_SHARED(log, folder + "/" + dataset.log);
  SLAMSWEEP_REQUIRE_SHARED(provenance_file, folder + "/PROVENANCE.txt");
  const DatasetStats stats = ReadStats(provenance_file);
  ASSERT_GT(stats.scans, 0u) << "no Stats line in " << provenance_file;

  const Sequence sequence = ReadCarmenSequence(log);
  EXPECT_EQ(sequence.scans.size(), stats.scans);
  for (const LaserScan& scan : sequence.scans) ASSERT_EQ(scan.BeamCount(), stats.beams);
  ASSERT_TRUE(sequence.reference.has_value());
  EXPECT_EQ(sequence.reference->size(), stats.scans);
  EXPECT_NO_THROW(ValidateSequence(sequence));
  EXPECT_NE(sequence.provenance.citation.find("Radish"), std::string::npos);
  if (stats.stamps_degenerate) {
    EXPECT_TRUE(AnyWarningContains(sequence, log.string() + ": recorded scan stamps are unusable"));
    EXPECT_EQ(sequence.scans.back().stamp_s, static_cast<double>(stats.scans - 1));
  }
}

INSTANTIATE_TEST_SUITE_P(Shared, CarmenDatasetTest,
                         ::testing::Values(DatasetCase{"intel", "intel-corrected.log.gz"},
                                           DatasetCase{"fr079", "freiburg-079-corrected.log.gz"},
                                           DatasetCase{"fr101", "freiburg-101-corrected.log.gz"},
                                           DatasetCase{"mit-csail", "csail-corrected.log.gz"},
                                           DatasetCase{"freiburg-campus", "freiburg-campus-corrected.log.gz"},
                                           DatasetCase{"mit-infinite-corridor", "infinite-corridor-corrected.log.gz"},
                                           DatasetCase{"orebro", "orebro-corrected.log.gz"},
                                           DatasetCase{"belgioioso", "belgioioso-corrected.log.gz"}),
                         [](const ::testing::TestParamInfo<DatasetCase>& info) {
                           std::string name = info.param.folder;
                           for (char& c : name) {
                             if (c == '-') c = '_';
                           }
                           return name;
                         });

TEST(CarmenDatasetFactsTest, IntelKeepsItsRecordedClockAndMarksNoReturnBeams) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  const Sequence sequence = ReadCarmenSequence(log);
  // First FLASER of the file: pose 0.600266 -0.0320327 -0.354665 at ipc_timestamp 32.9068.
  EXPECT_EQ(sequence.scans.front().stamp_s, 32.9068);
  EXPECT_EQ(sequence.scans.back().stamp_s, 2683.77);
  EXPECT_DOUBLE_EQ(sequence.reference->poses().front().position.x(), 0.600266);
  EXPECT_DOUBLE_EQ(sequence.reference->poses().front().Yaw(), -0.354665);
  // No PARAM robot_front_laser_max in intel: CARMEN's 80 m, so the 4172 readings of 81.83 m (counted
  // with awk) are the no-return beams and every other reading is a hit.
  std::size_t misses = 0;
  for (const LaserScan& scan : sequence.scans) {
    EXPECT_EQ(scan.range_max_m, 80.0);
    for (float range : scan.ranges_m) misses += scan.IsHit(range) ? 0 : 1;
  }
  EXPECT_EQ(misses, 4172u);
  // Four stamps in the file go back by up to 0.86 s (lines 5647, 10805, 11190, 12936): repaired, not
  // a reason to throw the clock away (the relations are on it).
  ASSERT_EQ(sequence.warnings.size(), 1u);
  EXPECT_NE(sequence.warnings[0].find("4 of 910 scan stamps"), std::string::npos) << sequence.warnings[0];
  EXPECT_NE(sequence.warnings[0].find("lines 5647, 10805, 11190, 12936"), std::string::npos) << sequence.warnings[0];
}

TEST(CarmenDatasetFactsTest, Fr079UsesTheMaxRangeParamOfItsLog) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/fr079/freiburg-079-corrected.log.gz");
  const Sequence sequence = ReadCarmenSequence(log);
  EXPECT_EQ(sequence.scans.front().range_max_m, 80.99);  // PARAM robot_front_laser_max 80.99
  EXPECT_DOUBLE_EQ(sequence.scans.front().angle_increment_rad, std::numbers::pi / 360);
  EXPECT_TRUE(sequence.warnings.empty());
}

}  // namespace
}  // namespace slamsweep::evaluator
