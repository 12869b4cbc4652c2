// The worker with MRPT's real SLAM programs (Debian mrpt-apps) on a short simulated sequence:
// each run must end ok with a map, a trajectory on the sequence clock and trajectory metrics that
// show the program tracked the robot. Labelled "slow" in ctest (a few seconds per run here).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "evaluator/sequence/sequence_file.h"
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
  // The simulated robot moves about 5 m in 150 scans through a mapped floor: a SLAM program that
  // tracks it stays within decimetres of the truth once aligned; a lost one is off by metres.
  EXPECT_LT(Metric(result, "ape_trans", "rmse"), 0.5) << result["metric_details"]["ape_trans"].dump();
  EXPECT_LT(Metric(result, "ape_rot", "rmse"), 10.0);

  const ev::OccupancyGrid map = ev::ReadMapServer(run_dir / "map.yaml");
  EXPECT_GT(map.CellCount(), 1000u);
  EXPECT_LT(Metric(result, "unknown_to_all", "value"), 1.0);
  EXPECT_FALSE(std::isnan(Metric(result, "corners", "value")));
  EXPECT_EQ(result["outputs"]["vector_map"], "map.geojson");
  return result;
}

TEST(WorkerMrptTest, IcpSlamRunsToAScoredResult_SlowTest) {
  if (!HaveProgram("icp-slam")) GTEST_SKIP() << "icp-slam not installed (Debian: mrpt-apps)";
  if (!ev::RawlogSupported()) GTEST_SKIP() << "this build cannot write rawlogs (MRPT not found)";
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
  if (!HaveProgram("rbpf-slam")) GTEST_SKIP() << "rbpf-slam not installed (Debian: mrpt-apps)";
  if (!ev::RawlogSupported()) GTEST_SKIP() << "this build cannot write rawlogs (MRPT not found)";
  const slamsweep::testing::TempDir dir;
  const nlohmann::json result = RunMrpt("mrpt-rbpf-slam", dir / "rbpf");
  // LOG_FREQUENCY = ceil(150 / 4) = 38: maps after steps 0, 38, 76 and 114.
  EXPECT_EQ(result["outputs"]["stage_count"], 4u);
  EXPECT_TRUE(fs::exists(dir / "rbpf" / "raw" / "maps" / "mapbuilt_00038__mrpt__maps__COccupancyGridMap2D_00.png"));
}

}  // namespace
}  // namespace slamsweep::orchestrator
