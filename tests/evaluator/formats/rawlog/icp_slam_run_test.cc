// Runs MRPT's icp-slam (Debian mrpt-apps) on a rawlog written by WriteRawlog: the proof that the
// rawlogs are what MRPT's SLAM programs need. Labelled "slow" in ctest (about 10-30 s).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "evaluator/formats/rawlog/rawlog_writer.h"
#include "evaluator/sequence/carmen_sequence.h"
#include "tests/evaluator/formats/rawlog/rawlog_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using rawlog_testing::HaveProgram;

constexpr const char* kIcpConfig = "/usr/share/mrpt/config_files/icp-slam/icp-slam_demo_classic_gridmatch.ini";
constexpr std::size_t kScans = 300;

std::string ReadAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

/// The installed example configuration with `overrides` (key -> value) applied to its `key=value` lines.
std::string EditedIni(const std::string& text, const std::map<std::string, std::string>& overrides) {
  std::istringstream in(text);
  std::string out;
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t equals = line.find('=');
    if (equals != std::string::npos) {
      std::string key = line.substr(0, equals);
      key.erase(std::remove_if(key.begin(), key.end(), [](char c) { return c == ' ' || c == '\t'; }), key.end());
      if (const auto found = overrides.find(key); found != overrides.end()) line = key + "=" + found->second;
    }
    out += line + "\n";
  }
  return out;
}

std::size_t CountLines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(IcpSlamRunTest, IcpSlamProcessesEveryStepOfAWrittenRawlogAndMapsTheBuilding) {
  if (!HaveProgram("icp-slam")) GTEST_SKIP() << "icp-slam not installed (Debian: mrpt-apps); MRPT run not checked";
  if (!std::filesystem::exists(kIcpConfig)) GTEST_SKIP() << "MRPT example config missing: " << kIcpConfig;
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");

  Sequence intel = ReadCarmenSequence(log);
  std::vector<std::size_t> first(kScans);
  std::iota(first.begin(), first.end(), 0);
  intel.scans.resize(kScans);
  intel.odometry = intel.odometry.Subset(first);
  const Trajectory reference = intel.reference->Subset(first);

  const testing::TempDir dir;
  const std::filesystem::path rawlog = dir / "intel300.rawlog";
  WriteRawlog(intel, rawlog);
  if (HaveProgram("rawlog-edit")) {
    const std::string command =
        "rawlog-edit --info -i '" + rawlog.string() + "' > '" + (dir / "info.txt").string() + "' 2>&1 < /dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    const std::string info = ReadAll(dir / "info.txt");
    EXPECT_NE(info.find("Overall number of objects         : 600"), std::string::npos) << info;
    EXPECT_NE(info.find("Actions/SensoryFrame format       : Yes"), std::string::npos) << info;
    EXPECT_NE(info.find("Earliest timestamp                : 32.906800"), std::string::npos) << info;
  }

  const std::filesystem::path out = dir / "out";
  testing::WriteFile(dir / "icp.ini", EditedIni(ReadAll(kIcpConfig), {{"rawlog_file", rawlog.string()},
                                                                      {"logOutput_dir", out.string()},
                                                                      {"SHOW_PROGRESS_3D_REAL_TIME", "0"},
                                                                      {"SAVE_3D_SCENE", "0"}}));
  // stdin from /dev/null: on an error icp-slam waits for a key press.
  const std::string command =
      "cd '" + dir.path().string() + "' && timeout 300 icp-slam icp.ini < /dev/null > run.log 2>&1";
  const int status = std::system(command.c_str());
  const std::string run_log = ReadAll(dir / "run.log");
  ASSERT_EQ(status, 0) << command << "\n" << run_log.substr(run_log.size() > 3000 ? run_log.size() - 3000 : 0);

  EXPECT_NE(run_log.find("STEP " + std::to_string(kScans) + " "), std::string::npos);
  EXPECT_NE(run_log.find("**END**"), std::string::npos);
  EXPECT_EQ(CountLines(ReadAll(out / "log_estimated_path.txt")), kScans);
  const std::string map_base = "_finalmaps_.txt_mrpt__maps__COccupancyGridMap2D_00";
  ASSERT_TRUE(std::filesystem::exists(out / (map_base + ".png")));
  ASSERT_GT(std::filesystem::file_size(out / (map_base + ".png")), 1000u);

  // "% Grid limits: [x_min x_max y_min y_max]" then four numbers (metres).
  std::istringstream limits(ReadAll(out / (map_base + "_limits.txt")));
  std::string comment;
  std::getline(limits, comment);
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
  ASSERT_TRUE(limits >> x_min >> x_max >> y_min >> y_max) << comment;
  // The first estimated pose ("step x y yaw"), where the first scan is always inserted, is on the map:
  // the odometry of the first action (the move from the odometry origin) reached icp-slam.
  std::istringstream path(ReadAll(out / "log_estimated_path.txt"));
  int step = -1;
  double x = 0, y = 0, yaw = 0;
  ASSERT_TRUE(path >> step >> x >> y >> yaw);
  EXPECT_EQ(step, 0);
  EXPECT_NEAR(x, intel.odometry.poses()[0].position.x(), 1e-5);
  EXPECT_NEAR(y, intel.odometry.poses()[0].position.y(), 1e-5);
  EXPECT_TRUE(x >= x_min && x <= x_max && y >= y_min && y <= y_max);
  // The map reaches across the building: its diagonal is at least the largest distance between two
  // reference poses (whatever frame ICP ends up in), and not absurdly more (a map blown up by
  // no-return beams would be; MRPT's grids grow in chunks and the config inserts up to 30 m).
  double diameter_m = 0.0;
  for (const Pose& a : reference.poses()) {
    for (const Pose& b : reference.poses()) diameter_m = std::max(diameter_m, (a.position - b.position).norm());
  }
  const double diagonal_m = std::hypot(x_max - x_min, y_max - y_min);
  EXPECT_GT(diagonal_m, diameter_m);
  EXPECT_LT(diagonal_m, diameter_m + 2 * 30.0 * std::sqrt(2.0) + 10.0);
}

}  // namespace
}  // namespace slamsweep::evaluator
