// Two independent implementations of tinySLAM (CoreSLAM) on the same input: slam-constructor's,
// which the tinyslam adapter runs, and BreezySLAM's RMHC_SLAM. They differ in details (BreezySLAM
// searches by random-mutation hill climbing in a fixed 1-pixel-per-cell map, slam-constructor by
// Monte-Carlo sampling in its own grid) but implement the same idea, so on a clean log both must
// track the robot to within the map's resolution scale, and on noisy odometry their errors must be
// of the same order. A driver that mangled the scans (wrong angles, units, frames) would fail both.
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

// BreezySLAM's headers expect their dependencies included first, as its own sources do.
#include <Laser.hpp>
#include <PoseChange.hpp>
#include <Position.hpp>
#include <algorithms.hpp>
#include <gtest/gtest.h>

#include "evaluator/formats/trajectory/trajectory_file.h"
#include "evaluator/sequence/robot_log.h"
#include "evaluator/sequence/sequence_file.h"
#include "evaluator/trajectory/ape.h"
#include "tests/cli/run_cli.h"
#include "tests/support/shared_data.h"

namespace slamsweep {
namespace {

namespace fs = std::filesystem;

/// intel's first 300 scans, as slamsweep writes program inputs, with the given odometry noise.
fs::path IntelInput(const fs::path& dir, const std::string& noise) {
  const fs::path full = dir / ("intel-" + noise + ".log");
  std::vector<std::string> args = {"data", "convert", "intel", "--to", "carmen", "-o", full.string(), "--seed", "7"};
  if (noise != "clean") args.insert(args.end(), {"--odometry-noise", noise});
  const auto convert = testing::RunCli(args);
  EXPECT_EQ(convert.exit_code, 0) << convert.err;
  std::ifstream in(full);
  const fs::path cut = dir / ("intel-300-" + noise + ".log");
  std::ofstream out(cut);
  int scans = 0;
  for (std::string line; std::getline(in, line) && scans < 300;) {
    out << line << '\n';
    if (line.rfind("FLASER", 0) == 0) ++scans;
  }
  return cut;
}

evaluator::Trajectory RunBreezySlam(const evaluator::RobotLog& robot) {
  const evaluator::LaserScan& first = robot.scans.front();
  const int beams = static_cast<int>(first.BeamCount());
  const double fan_deg = first.angle_increment_rad * (beams - 1) * 180.0 / M_PI;
  Laser laser(beams, 10.0f, static_cast<float>(fan_deg), static_cast<float>(first.range_max_m * 1000.0));
  // 0.1 m cells over 100 m, as slam-constructor's tiny_slam_base.properties.
  RMHC_SLAM slam(laser, 1000, 100.0, 1);
  evaluator::Trajectory trajectory;
  std::vector<int> scan_mm(beams);
  for (std::size_t i = 0; i < robot.scans.size(); ++i) {
    const evaluator::LaserScan& scan = robot.scans[i];
    for (int b = 0; b < beams; ++b) {
      scan_mm[b] = scan.IsHit(scan.ranges_m[b]) ? static_cast<int>(std::lround(scan.ranges_m[b] * 1000.0)) : 0;
    }
    double forward_mm = 0, turn_deg = 0, dt = 0;
    if (i > 0) {
      const evaluator::Pose& a = robot.odometry.poses()[i - 1];
      const evaluator::Pose& b = robot.odometry.poses()[i];
      const double dx = b.position.x() - a.position.x(), dy = b.position.y() - a.position.y();
      forward_mm = 1000.0 * (std::cos(a.Yaw()) * dx + std::sin(a.Yaw()) * dy);
      turn_deg = std::remainder(b.Yaw() - a.Yaw(), 2 * M_PI) * 180.0 / M_PI;
      dt = scan.stamp_s - robot.scans[i - 1].stamp_s;
    }
    PoseChange change(forward_mm, turn_deg, dt);
    slam.update(scan_mm.data(), change);
    const Position& position = slam.getpos();
    trajectory.Add(scan.stamp_s, evaluator::Pose::Planar(position.x_mm / 1000.0, position.y_mm / 1000.0,
                                                         position.theta_degrees * M_PI / 180.0));
  }
  return trajectory;
}

evaluator::Trajectory RunTinySlam(const fs::path& input, const fs::path& out) {
  const std::string command = std::string(TINYSLAM_DRIVER) + " --input " + input.string() + " --output-dir " +
                              out.string() + " --seed 1 --stages 0 > " + (out.string() + ".log") + " 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  return evaluator::ReadTrajectory(out / "trajectory.tum");
}

double Ate(const evaluator::Trajectory& reference, const evaluator::Trajectory& estimate) {
  evaluator::ApeOptions options;
  options.alignment.mode = evaluator::AlignmentMode::kSe2;
  return evaluator::Ape(options).Compute(reference, estimate).statistics.rmse;
}

TEST(TinySlamCrossCheckTest, SlamConstructorAndBreezySlamAgreeOnIntel) {
  SLAMSWEEP_REQUIRE_SHARED(intel, "datasets/intel/intel-corrected.log.gz");
  testing::TempDir dir;
  const evaluator::Sequence truth = evaluator::ReadSequence(intel);
  ASSERT_TRUE(truth.reference.has_value());
  int case_index = 0;
  for (const std::string noise : {"clean", "0.02,0.001,0.02,0.001"}) {
    const fs::path input = IntelInput(dir.path(), noise);
    evaluator::Sequence written = evaluator::ReadSequence(input);
    const evaluator::RobotLog robot = evaluator::TakeRobotLog(written);
    std::vector<std::size_t> first(robot.scans.size());
    for (std::size_t i = 0; i < first.size(); ++i) first[i] = i;
    const evaluator::Trajectory reference = truth.reference->Subset(first);
    const double breezy = Ate(reference, RunBreezySlam(robot));
    const double tiny = Ate(reference, RunTinySlam(input, dir / ("tiny-" + std::to_string(case_index++))));
    const double odometry = Ate(reference, robot.odometry);
    std::cout << "[ tinySLAM ] intel-300 " << noise << ": slam-constructor " << tiny << " m, BreezySLAM " << breezy
              << " m, odometry " << odometry << " m\n";
    if (noise == "clean") {
      // Odometry = reference here: a matcher that reads the scans right stays near it over the 300
      // scans (measured: slam-constructor 0.26 m, BreezySLAM's hill climbing 1.67 m); mirrored beam
      // angles, wrong units or frames pull a matcher tens of metres away.
      EXPECT_LT(tiny, 2.5);
      EXPECT_LT(breezy, 2.5);
    } else {
      // Same order: neither more than 4x the other.
      EXPECT_LT(tiny, 4.0 * breezy);
      EXPECT_LT(breezy, 4.0 * tiny);
    }
  }
}

}  // namespace
}  // namespace slamsweep
