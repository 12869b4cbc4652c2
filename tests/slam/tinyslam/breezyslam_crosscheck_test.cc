// Two independent implementations of tinySLAM (CoreSLAM) on the same input: slam-constructor's,
// which the tinyslam adapter runs, and BreezySLAM's RMHC_SLAM. They differ in details (BreezySLAM
// searches by random-mutation hill climbing in a fixed 1-pixel-per-cell map, slam-constructor by
// Monte-Carlo sampling in its own grid) but implement the same idea. On a clean log both must track
// the robot (a driver that mangled the scans, with wrong angles, units or frames, fails both). On
// noisy odometry both are held to the odometry baseline by a one-sided sign test over ten seeded
// draws: BreezySLAM must beat it, which shows the input is one a tinySLAM can solve, and
// slam-constructor's verdict must be the one the roster's expected-failures list records for it.
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

#include <nlohmann/json.hpp>

#include "evaluator/formats/trajectory/trajectory_file.h"
#include "evaluator/sequence/robot_log.h"
#include "evaluator/sequence_io/sequence_file.h"
#include "evaluator/statistics/sign_test.h"
#include "evaluator/trajectory_metrics/ape.h"
#include "evaluator/trajectory_metrics/relations_metric.h"
#include "evaluator/catalog/catalog.h"
#include "tests/cli/run_cli.h"
#include "tests/support/shared_data.h"

namespace slamsweep {
namespace {

namespace fs = std::filesystem;

/// intel's first 300 scans, as slamsweep writes program inputs, with the given odometry noise drawn around the
/// reference (stated: the catalog's default on corrected logs is the robot's recorded odometry).
fs::path IntelInput(const fs::path& dir, const std::string& noise, int seed) {
  const fs::path full = dir / ("intel-" + noise + "-" + std::to_string(seed) + ".log");
  std::vector<std::string> args = {
      "data",   "convert",           "intel", "--to", "carmen", "--odometry", "reference", "-o", full.string(),
      "--seed", std::to_string(seed)};
  if (noise != "clean") args.insert(args.end(), {"--odometry-noise", noise});
  const auto convert = testing::RunCli(args);
  EXPECT_EQ(convert.exit_code, 0) << convert.err;
  std::ifstream in(full);
  const fs::path cut = dir / ("intel-300-" + noise + "-" + std::to_string(seed) + ".log");
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

/// The ATEs of slam-constructor's tinySLAM, BreezySLAM and the odometry on intel's first 300 scans.
struct Errors {
  double tiny = 0.0;
  double breezy = 0.0;
  double odometry = 0.0;
};

Errors RunBoth(const fs::path& dir, const evaluator::Sequence& truth, const std::string& noise, int seed) {
  const fs::path input = IntelInput(dir, noise, seed);
  evaluator::Sequence written = evaluator::ReadSequence(input);
  const evaluator::RobotLog robot = evaluator::TakeRobotLog(written);
  std::vector<std::size_t> first(robot.scans.size());
  for (std::size_t i = 0; i < first.size(); ++i) first[i] = i;
  const evaluator::Trajectory reference = truth.reference->Subset(first);
  Errors errors;
  errors.breezy = Ate(reference, RunBreezySlam(robot));
  errors.tiny = Ate(reference, RunTinySlam(input, dir / ("tiny-" + noise + "-" + std::to_string(seed))));
  errors.odometry = Ate(reference, robot.odometry);
  std::cout << "[ tinySLAM ] intel-300 " << noise << " seed " << seed << ": slam-constructor " << errors.tiny
            << " m, BreezySLAM " << errors.breezy << " m, odometry " << errors.odometry << " m\n";
  return errors;
}

TEST(TinySlamCrossCheckTest, SlamConstructorAndBreezySlamAgainstTheOdometryOnIntel) {
  SLAMSWEEP_REQUIRE_SHARED(intel, "datasets/intel/intel-corrected.log.gz");
  testing::TempDir dir;
  const evaluator::Sequence truth = evaluator::ReadSequence(intel);
  ASSERT_TRUE(truth.reference.has_value());

  // Odometry = reference here: a matcher that reads the scans right stays near it over the 300 scans
  // (measured: slam-constructor 0.15 m, BreezySLAM's hill climbing 1.67 m); mirrored beam angles,
  // wrong units or frames pull a matcher tens of metres away.
  const Errors clean = RunBoth(dir.path(), truth, "clean", 7);
  EXPECT_LT(clean.tiny, 2.5);
  EXPECT_LT(clean.breezy, 2.5);

  // configs/paper.yaml's 5 % odometry noise (variances), ten seeded draws. Measured when this was
  // written: BreezySLAM beat the odometry in 10 of 10 draws, slam-constructor's tinySLAM in 4.
  constexpr int kDraws = 10;
  std::vector<double> tiny, breezy, odometry;
  for (int seed = 1; seed <= kDraws; ++seed) {
    const Errors errors = RunBoth(dir.path(), truth, "0.0025,0.0004,0.0025,0.0001", seed);
    tiny.push_back(errors.tiny);
    breezy.push_back(errors.breezy);
    odometry.push_back(errors.odometry);
  }
  const evaluator::SignTestResult breezy_test = evaluator::OneSidedSignTest(breezy, odometry);
  const evaluator::SignTestResult tiny_test = evaluator::OneSidedSignTest(tiny, odometry);
  std::cout << "[ tinySLAM ] wins over the odometry: BreezySLAM " << breezy_test.wins << " (p = " << breezy_test.p_value
            << "), slam-constructor " << tiny_test.wins << " (p = " << tiny_test.p_value << ") of " << kDraws << "\n";
  EXPECT_LE(breezy_test.p_value, 0.05) << "the independent tinySLAM no longer beats the odometry on this input";
  std::ifstream list(std::string(SLAMSWEEP_SOURCE_DIR) + "/tests/slam/roster_expected_failures.json");
  const nlohmann::json expected_failures = nlohmann::json::parse(list);
  bool listed = false;
  for (const auto& entry : expected_failures.at("expected_failures"))
    listed = listed || entry.at("algorithm") == "tinyslam";
  if (listed) {
    EXPECT_GT(tiny_test.p_value, 0.05) << "slam-constructor's tinySLAM now beats the odometry here: take it off "
                                          "tests/slam/roster_expected_failures.json if the roster test agrees";
  } else {
    EXPECT_LE(tiny_test.p_value, 0.05) << "slam-constructor's tinySLAM does not beat the odometry here";
  }
}

// Dense real data with the robot's own odometry: the full-rate intel log (every scan of the run's first
// 1,088.6 s), scored on the 1,033 relations inside it. Whether a tinySLAM can beat the wheels there tells a
// failure of the algorithm from one of an implementation. Measured when this was written (one seed each):
// BreezySLAM 6.18 m, slam-constructor 6.51 m, the odometry 3.48 m: neither tinySLAM beats the wheels on this
// run, so slam-constructor's miss there (roster_expected_failures.json) is the algorithm's, not our driver's.
TEST(TinySlamCrossCheckTest, BothTinySlamsAgainstTheWheelsOnTheFullRateIntelLog) {
  SLAMSWEEP_REQUIRE_SHARED(raw, "datasets/intel/intel-raw-scans-0-5504.clf.gz");
  SLAMSWEEP_REQUIRE_SHARED(relations, "datasets/intel/intel.relations");
  testing::TempDir dir;
  const fs::path input = dir / "intel-full-rate.log";
  const auto convert = testing::RunCli({"data", "convert", "intel-full-rate", "--to", "carmen", "-o", input.string()});
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  const auto catalog = evaluator::ReadCatalog(std::filesystem::path(SLAMSWEEP_SOURCE_DIR) / "configs/datasets.yaml");
  const evaluator::Sequence truth = evaluator::LoadCatalogSequence(
      evaluator::FindCatalogEntry(catalog, "intel-full-rate"), {{"SHARED", testing::SharedRoot().string()}});
  ASSERT_TRUE(truth.relations.has_value());
  evaluator::Sequence written = evaluator::ReadSequence(input);
  const evaluator::RobotLog robot = evaluator::TakeRobotLog(written);
  const auto relations_error = [&](const evaluator::Trajectory& estimate) {
    return evaluator::RelationsMetric({}).Compute(estimate, *truth.relations, &robot.odometry).translation_abs_mean_m;
  };
  const double odometry = relations_error(robot.odometry);
  const double breezy = relations_error(RunBreezySlam(robot));
  const double tiny = relations_error(RunTinySlam(input, dir / "tiny"));
  std::cout << "[ tinySLAM ] intel-full-rate, relations error: BreezySLAM " << breezy << " m, slam-constructor " << tiny
            << " m, odometry " << odometry << " m\n";
  EXPECT_GT(breezy, odometry) << "the independent tinySLAM now beats the wheels on the full-rate log: "
                                 "slam-constructor's miss there may be our driver's";
  EXPECT_GT(tiny, 0.0);
}

}  // namespace
}  // namespace slamsweep
