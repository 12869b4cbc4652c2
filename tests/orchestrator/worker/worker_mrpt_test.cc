// The worker with MRPT's real SLAM programs (Debian mrpt-apps) on a short simulated sequence with
// noisy odometry: each run must end ok with a map, a trajectory on the sequence clock, and end closer
// to the truth than the odometry it was given (the odometry baseline's ATE on the same draw).
// Labelled "slow" in ctest (a few seconds per run here).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "evaluator/sequence_io/sequence_file.h"
#include "evaluator/trajectory_metrics/ape.h"
#include "orchestrator/adapters/run_inputs.h"
#include "orchestrator/worker/worker.h"
#include "tests/orchestrator/worker/run_spec_fixture.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

namespace ev = slamsweep::evaluator;
namespace fs = std::filesystem;

constexpr std::size_t kScans = 150;

bool HaveProgram(const std::string& program) {
  return std::system(("command -v " + program + " > /dev/null 2>&1").c_str()) == 0;
}

double Metric(const nlohmann::json& result, const std::string& metric, const std::string& statistic) {
  for (const nlohmann::json& entry : result["metrics"]) {
    if (entry["metric"] == metric && entry["statistic"] == statistic) return entry["value"].get<double>();
  }
  return std::nan("");
}

/// Runs `adapter` on 150 simulated scans and checks what every MRPT run must give.
nlohmann::json RunMrpt(const std::string& adapter, const fs::path& run_dir) {
  RunSpec spec = testing::SimulatedRun(adapter, kScans);
  spec.evaluation.align = "se2";
  // About 20 % of every distance and turn and 8 deg of heading per metre (the alphas are variances),
  // one seeded draw: over these 150 scans the odometry is 4.7 cm RMSE off the truth after alignment
  // (measured when this was written: icp-slam 2.0 cm, rbpf-slam 2.7 cm).
  spec.noise.name = "noisy";
  spec.noise.odometry = ev::OdometryNoise{0.05, 0.02, 0.04, 0.01, 0.0, 0.0};
  spec.seed = 7;
  testing::WriteRunJson(run_dir, spec);
  EXPECT_EQ(RunWorker(run_dir), kWorkerWroteResult);
  const nlohmann::json result = testing::ReadJson(run_dir / "result.json");
  EXPECT_EQ(result["status"], "ok") << result.dump(2) << "\n" << testing::ReadText(run_dir / "log.txt").substr(0, 3000);
  ::testing::Test::RecordProperty("wall_s", std::to_string(result["wall_s"].get<double>()));

  // One pose per scan, stamped with the scans' stamps (step k = scan k).
  const ev::Trajectory estimate = ev::ReadTum(run_dir / "trajectory.tum");
  const ev::Trajectory reference = ev::ReadTum(run_dir / "reference.tum");
  EXPECT_EQ(estimate.size(), kScans);
  EXPECT_EQ(estimate.stamps_s(), reference.stamps_s());
  EXPECT_EQ(Metric(result, "ape_trans", "n"), static_cast<double>(kScans));
  // The claim: closer to the truth than the odometry the program was handed (the same inputs the worker
  // prepared, scored the same way).
  const RunInputs inputs = PrepareRunInputs(spec);
  ev::ApeOptions options;
  options.alignment.mode = ev::AlignmentMode::kSe2;
  const double odometry_ate_m =
      ev::Ape(options).Compute(*inputs.truth.reference, inputs.robot.odometry).statistics.rmse;
  const double ate_m = Metric(result, "ape_trans", "rmse");
  std::cout << "[ mrpt ] " << adapter << " ATE " << ate_m << " m, its odometry " << odometry_ate_m << " m\n";
  EXPECT_LT(ate_m, odometry_ate_m) << result["metric_details"]["ape_trans"].dump();

  const ev::OccupancyGrid map = ev::ReadMapServer(run_dir / "map.yaml");
  EXPECT_GT(map.CellCount(), 1000u);
  EXPECT_LT(Metric(result, "unknown_to_all", "value"), 1.0);
  EXPECT_FALSE(std::isnan(Metric(result, "corners", "value")));
  return result;
}

TEST(WorkerMrptTest, IcpSlamRunsToAScoredResult_SlowTest) {
  if (!HaveProgram("icp-slam")) SLAMSWEEP_SKIP_OR_FAIL_IN_CI("icp-slam not installed (Debian: mrpt-apps)");
  if (!ev::RawlogSupported()) SLAMSWEEP_SKIP_OR_FAIL_IN_CI("this build cannot write rawlogs (MRPT not found)");
  const slamsweep::testing::TempDir dir;
  const nlohmann::json result = RunMrpt("mrpt-icp-slam", dir / "icp");
  EXPECT_EQ(result["command"], nlohmann::json({"icp-slam", "../input/icp-slam.ini"}));
  // icp-slam saves no stage maps: they are rendered from its path, evaluation.stages of them.
  EXPECT_EQ(result["outputs"]["stage_count"], 4u);
  const std::string ini = testing::ReadText(dir / "icp" / "input" / "icp-slam.ini");
  EXPECT_NE(ini.find("rawlog_file=../input/simulated-floor.rawlog"), std::string::npos);
  EXPECT_NE(ini.find("SHOW_PROGRESS_3D_REAL_TIME=0"), std::string::npos);
}

TEST(WorkerMrptTest, RbpfSlamRunsToAScoredResultWithItsOwnStageMaps_SlowTest) {
  if (!HaveProgram("rbpf-slam")) SLAMSWEEP_SKIP_OR_FAIL_IN_CI("rbpf-slam not installed (Debian: mrpt-apps)");
  if (!ev::RawlogSupported()) SLAMSWEEP_SKIP_OR_FAIL_IN_CI("this build cannot write rawlogs (MRPT not found)");
  const slamsweep::testing::TempDir dir;
  const nlohmann::json result = RunMrpt("mrpt-rbpf-slam", dir / "rbpf");
  // LOG_FREQUENCY = ceil(150 / 4) = 38: maps after steps 0, 38, 76 and 114.
  EXPECT_EQ(result["outputs"]["stage_count"], 4u);
  EXPECT_TRUE(fs::exists(dir / "rbpf" / "raw" / "maps" / "mapbuilt_00038__mrpt__maps__COccupancyGridMap2D_00.png"));
}

}  // namespace
}  // namespace slamsweep::orchestrator
