#include "evaluator/sequence/relations_clock.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "evaluator/core/input_error.h"
#include "tests/evaluator/sequence/room_scan.h"

namespace slamsweep::evaluator {
namespace {

using testing::RoomScan;

/// A robot weaving through the room: it drives, turns and turns back, never still.
Pose WeavingPose(double t_s) {
  return Pose::Planar(2.0 + 1.5 * std::sin(0.4 * t_s), 0.8 * std::sin(0.25 * t_s), 0.6 * std::sin(0.3 * t_s));
}

// The relations' clock: t_log = kRate * t_relations + kOffset. The scans' fit is good to about 20 ms
// here (its halves, 40 s each, set the rate), well inside the 0.15 s lag the second test tells apart.
constexpr double kOffsetS = -1000.123;
constexpr double kRate = 1.00002;

/// Scans every 0.2 s with a few centimetres of jitter on the log's clock, and relations 0.8 s apart on
/// their own clock at times that fall between scans, as a relations file made from the full-rate log.
struct Drive {
  std::vector<LaserScan> scans;
  Trajectory readings;
  Relations relations;
};

Drive WeavingDrive(double odometry_lag_s) {
  Drive drive;
  for (int i = 0; i < 400; ++i) {
    const double t = 0.2 * i + 0.03 * std::sin(1.7 * i);
    LaserScan scan = RoomScan(WeavingPose(t));
    scan.stamp_s = t;
    drive.scans.push_back(scan);
  }
  // Odometry readings every 0.05 s, stamped late by the lag (a reading is logged after the motion).
  for (int i = 0; i < 1600; ++i) drive.readings.Add(0.05 * i + odometry_lag_s, WeavingPose(0.05 * i));
  for (double t = 1.07; t + 0.8 < 78.0; t += 0.8) {
    drive.relations.push_back(
        {(t - kOffsetS) / kRate, (t + 0.8 - kOffsetS) / kRate, Relative(WeavingPose(t), WeavingPose(t + 0.8))});
  }
  return drive;
}

double MappedOffsetAt(double offset_s, double rate, double relation_t_s) {
  return offset_s + (rate - 1.0) * relation_t_s;
}

TEST(RelationsClockByScansTest, FindsTheMapThatLaysEachRelationOnItsScans) {
  const Drive drive = WeavingDrive(0.0);
  const double middle = drive.relations[drive.relations.size() / 2].t1_s;
  const double truth = MappedOffsetAt(kOffsetS, kRate, middle);
  // Started 0.3 s off, as an odometry fit of a lagging stream would start it.
  const SearchedClockFit fit = FitRelationsClockByScans(drive.relations, drive.scans, drive.readings, truth + 0.3);
  EXPECT_NEAR(MappedOffsetAt(fit.offset_s, fit.rate, middle), truth, 0.025);
  EXPECT_LT(fit.disagreement, fit.next_best_disagreement);
  EXPECT_EQ(fit.relations, drive.relations.size());
}

TEST(RelationsClockByScansTest, OdometryThatLagsTheLaserMovesTheOdometryFitButNotTheScans) {
  const Drive drive = WeavingDrive(0.15);
  const double middle = drive.relations[drive.relations.size() / 2].t1_s;
  const double truth = MappedOffsetAt(kOffsetS, kRate, middle);
  const SearchedClockFit by_odometry = FitRelationsClockByOdometry(drive.relations, drive.readings);
  EXPECT_NEAR(MappedOffsetAt(by_odometry.offset_s, by_odometry.rate, middle), truth + 0.15, 0.01);
  const SearchedClockFit by_scans =
      FitRelationsClockByScans(drive.relations, drive.scans, drive.readings, truth + 0.15);
  EXPECT_NEAR(MappedOffsetAt(by_scans.offset_s, by_scans.rate, middle), truth, 0.025);
}

TEST(RelationsClockByScansTest, TooFewScansOrRelationsAreAnInputError) {
  const Drive drive = WeavingDrive(0.0);
  EXPECT_THROW(
      FitRelationsClockByScans(drive.relations, std::vector<LaserScan>(drive.scans.begin(), drive.scans.begin() + 1),
                               drive.readings, 0.0),
      InputError);
  EXPECT_THROW(FitRelationsClockByScans(Relations(drive.relations.begin(), drive.relations.begin() + 3), drive.scans,
                                        drive.readings, kOffsetS),
               InputError);
  // No offset in the window puts a relation inside the scans.
  EXPECT_THROW(FitRelationsClockByScans(drive.relations, drive.scans, drive.readings, kOffsetS + 500.0), InputError);
}

}  // namespace
}  // namespace slamsweep::evaluator
