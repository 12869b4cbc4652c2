// Runs MRPT's icp-slam and rbpf-slam (Debian mrpt-apps) on rawlogs written by WriteRawlog: the proof
// that the rawlogs are what MRPT's SLAM programs need. Each run gets intel's first scans with noisy
// odometry (the corrected log's odometry is the reference itself, which a program could simply echo),
// must process every step, write a final grid map that covers its own path and scores within a sane
// range on the paper metrics, and end closer to the reference than the noisy odometry it was given.
// Labelled "slow" in ctest (about 10-60 s each on a loaded 2-core machine).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "evaluator/formats/map/map_file.h"
#include "evaluator/formats/rawlog/rawlog_writer.h"
#include "evaluator/formats/trajectory/mrpt_path_format.h"
#include "evaluator/map_metrics/paper_metrics.h"
#include "evaluator/noise/odometry_noise.h"
#include "evaluator/sequence/carmen_sequence.h"
#include "evaluator/trajectory_metrics/ape.h"
#include "orchestrator/adapters/mrpt_adapters.h"
#include "orchestrator/adapters/mrpt_ini.h"
#include "tests/evaluator/formats/rawlog/rawlog_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using rawlog_testing::HaveProgram;

// icp-slam runs with the orchestrator adapter's template and defaults, so that this test checks the
// configuration sweeps use (see IcpSlamDefaultSettings for why the template alone diverges on intel).
constexpr const char* kIcpConfig = orchestrator::kIcpSlamTemplate;
constexpr const char* kRbpfConfig = "/usr/share/mrpt/config_files/rbpf-slam/gridmapping_intel.ini";
constexpr std::size_t kScans = 300;
/// rbpf-slam with MRPT's intel settings (optimal-sampling particle filter) and 5 particles takes
/// about 50 ms a step here (10 s for 200 steps on a loaded 2-core machine): 300 steps stay well
/// under a minute.
constexpr std::size_t kRbpfScans = kScans;

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

/// The first `count` scans of intel (odometry and reference cut to match), the odometry made noisy:
/// configs/paper.yaml's 5 % (the alphas are variances), drawn with a fixed seed, which drifts the
/// odometry by metres over 300 scans.
struct IntelPrefix {
  Sequence sequence;
  Trajectory reference;
  /// The ATE (se2 RMSE) of the noisy odometry itself: the odometry baseline a SLAM program must beat.
  double odometry_ate_m = 0.0;
};

IntelPrefix FirstIntelScans(const std::filesystem::path& log, std::size_t count) {
  Sequence intel = ReadCarmenSequence(log);
  std::vector<std::size_t> first(count);
  std::iota(first.begin(), first.end(), 0);
  intel.scans.resize(count);
  Trajectory reference = intel.reference->Subset(first);
  OdometryNoise noise;
  noise.alpha1 = 0.0025;
  noise.alpha2 = 0.0004;
  noise.alpha3 = 0.0025;
  noise.alpha4 = 0.0001;
  intel.odometry = ApplyOdometryNoise(intel.odometry.Subset(first), noise, /*seed=*/7);
  ApeOptions ape_options;
  ape_options.alignment.mode = AlignmentMode::kSe2;
  const double odometry_ate_m = Ape(ape_options).Compute(reference, intel.odometry).statistics.rmse;
  return {std::move(intel), std::move(reference), odometry_ate_m};
}

/// The ATE (se2) of a run's log_estimated_path.txt against the reference, checked to pair every scan.
double RunAte(const std::filesystem::path& out_dir, const IntelPrefix& prefix) {
  std::vector<double> step_stamps_s;
  for (const LaserScan& scan : prefix.sequence.scans) step_stamps_s.push_back(scan.stamp_s);
  const Trajectory estimate = ReadMrptPath(out_dir / "log_estimated_path.txt", step_stamps_s);
  ApeOptions ape_options;
  ape_options.alignment.mode = AlignmentMode::kSe2;
  const MetricResult ape = Ape(ape_options).Compute(prefix.reference, estimate);
  EXPECT_EQ(ape.pairs, prefix.sequence.scans.size());
  return ape.statistics.rmse;
}

/// The final grid map a run wrote in `dir` (not its sub-folders, which hold the intermediate ones):
/// MRPT names it "<prefix>_mrpt__maps__COccupancyGridMap2D_00.png" beside "..._limits.txt".
std::filesystem::path FinalGridMap(const std::filesystem::path& dir) {
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().filename().string().ends_with("_COccupancyGridMap2D_00.png")) return entry.path();
  }
  return {};
}

/// Checks that a SLAM program's final map is a map of the part of intel it was given: it covers
/// every pose of the program's own estimated path (the map's frame; within `insertion_distance_m`,
/// see below), and the paper metrics of it are in a sane range.
void ExpectSaneFinalMap(const std::filesystem::path& out_dir, double insertion_distance_m) {
  const std::filesystem::path map_file = FinalGridMap(out_dir);
  ASSERT_FALSE(map_file.empty()) << "no *_COccupancyGridMap2D_00.png in " << out_dir;
  ASSERT_EQ(DetectMapFormat(map_file), MapFormat::kMrptGridmap) << map_file;
  const OccupancyGrid grid = ReadMap(map_file);
  ASSERT_GT(grid.CellCount(), 0u);

  // The map and the estimated path share the program's frame. Both programs insert a scan into the
  // grid only after the robot moved insertionLinDistance from the last inserted one, and the grid
  // holds the sensor position of every inserted scan (its rays start there): every estimated pose is
  // within that distance of the map, not necessarily on it (a program inserting every 2 m leaves the
  // end of a corridor it turned back in outside its grid). 0.1 m more for the cell rounding.
  const double tolerance_m = insertion_distance_m + 0.1;
  std::vector<Eigen::Vector2d> estimated_path;
  {
    // "step x y ..." per step (icp-slam: step x y yaw; rbpf-slam: step x y z yaw pitch roll stamp).
    std::istringstream path_text(ReadAll(out_dir / "log_estimated_path.txt"));
    for (std::string line; std::getline(path_text, line);) {
      if (line.empty() || line.front() == '%') continue;
      std::istringstream fields(line);
      double step = 0, x = 0, y = 0;
      if (fields >> step >> x >> y) estimated_path.emplace_back(x, y);
    }
  }
  ASSERT_FALSE(estimated_path.empty());
  const double x_max_m = grid.origin.x_m + grid.width * grid.resolution_m;
  const double y_max_m = grid.origin.y_m + grid.height * grid.resolution_m;
  for (std::size_t i = 0; i < estimated_path.size(); ++i) {
    const Eigen::Vector2d& p = estimated_path[i];
    const bool covered = p.x() > grid.origin.x_m - tolerance_m && p.x() < x_max_m + tolerance_m &&
                         p.y() > grid.origin.y_m - tolerance_m && p.y() < y_max_m + tolerance_m;
    // The first uncovered pose is reported; the metrics below are still checked.
    EXPECT_TRUE(covered) << "estimated pose " << i << " (" << p.x() << ", " << p.y() << ") outside the map ["
                         << grid.origin.x_m << ", " << x_max_m << "] x [" << grid.origin.y_m << ", " << y_max_m
                         << "]; MRPT limits file: "
                         << ReadAll(map_file.parent_path() / (map_file.stem().string() + "_limits.txt"));
    if (!covered) break;
  }

  const PaperMetrics metrics = ComputePaperMetrics(grid);
  const std::string summary = metrics.ToJson().dump();
  ::testing::Test::RecordProperty("paper_metrics", summary);
  // Corners: walls meet in corners, so a map of a building has some. A map of noise (scattered
  // single hits, a diverged filter smearing walls) has a corner response almost everywhere there is
  // structure; real walls are thin lines whose corners are a small share of the cells: 1 in 100 is
  // far above what a building plan at 5 cm has and far below what noise gives.
  EXPECT_GT(metrics.corners.corners, 0) << summary;
  EXPECT_LT(metrics.corners.corners, static_cast<std::int64_t>(grid.CellCount() / 100)) << summary;
  // Enclosed areas: the metric counts every closed free pocket of at least min_area_cells cells,
  // maximised over how unknown cells are binarised, so besides rooms it also counts the small gaps
  // between wall fragments of a 5 cm grid: it is far from the number of rooms. A map broken into
  // noise has such pockets everywhere, one every few dozen known cells. One pocket per 1000 known
  // cells (2.5 m^2 of floor at 5 cm, a cubicle) is far above a consistent map and far below noise.
  // At least one: the explored free space is surrounded by walls and unknown cells, not the border.
  const std::int64_t known_cells = metrics.occupied.total_cells - metrics.occupied.unknown_cells;
  EXPECT_GT(metrics.enclosed.enclosed_areas, 0) << summary;
  EXPECT_LT(metrics.enclosed.enclosed_areas, known_cells / 1000) << summary;
}

TEST(IcpSlamRunTest, IcpSlamProcessesEveryStepOfAWrittenRawlogAndMapsTheBuilding) {
  if (!HaveProgram("icp-slam"))
    SLAMSWEEP_SKIP_OR_FAIL_IN_CI("icp-slam not installed (Debian: mrpt-apps); MRPT run not checked");
  if (!std::filesystem::exists(kIcpConfig)) SLAMSWEEP_SKIP_OR_FAIL_IN_CI("MRPT example config missing: " << kIcpConfig);
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");

  const IntelPrefix prefix = FirstIntelScans(log, kScans);
  const Sequence& intel = prefix.sequence;
  const Trajectory& reference = prefix.reference;

  const testing::TempDir dir;
  const std::filesystem::path rawlog = dir / "intel300.rawlog";
  WriteRawlog(RobotLogOf(intel), rawlog);
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
  std::vector<orchestrator::IniSetting> settings = orchestrator::IcpSlamDefaultSettings();
  for (const auto& [key, value] : std::map<std::string, std::string>{{"rawlog_file", rawlog.string()},
                                                                     {"logOutput_dir", out.string()},
                                                                     {"SHOW_PROGRESS_3D_REAL_TIME", "0"},
                                                                     {"SAVE_3D_SCENE", "0"}}) {
    settings.push_back({"MappingApplication", key, value});
  }
  testing::WriteFile(dir / "icp.ini", orchestrator::RenderIni(ReadAll(kIcpConfig), settings));
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

  ExpectSaneFinalMap(out, /*insertion_distance_m=*/0.5);  // the adapter's insertionLinDistance

  // The claim: closer to the reference than the odometry it was given (the baseline's ATE on the same draw).
  const double ate_m = RunAte(out, prefix);
  std::cout << "[ mrpt ] icp-slam ATE " << ate_m << " m, noisy odometry " << prefix.odometry_ate_m << " m\n";
  EXPECT_GT(prefix.odometry_ate_m, 1.0) << "the noise must give the scan matcher real work";
  EXPECT_LT(ate_m, prefix.odometry_ate_m);
}

TEST(IcpSlamRunTest, RbpfSlamProcessesEveryStepOfAWrittenRawlogAndMapsTheBuilding) {
  if (!HaveProgram("rbpf-slam"))
    SLAMSWEEP_SKIP_OR_FAIL_IN_CI("rbpf-slam not installed (Debian: mrpt-apps); MRPT run not checked");
  if (!std::filesystem::exists(kRbpfConfig))
    SLAMSWEEP_SKIP_OR_FAIL_IN_CI("MRPT example config missing: " << kRbpfConfig);
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");

  const IntelPrefix prefix = FirstIntelScans(log, kRbpfScans);
  const testing::TempDir dir;
  const std::filesystem::path rawlog = dir / "intel.rawlog";
  WriteRawlog(RobotLogOf(prefix.sequence), rawlog);

  const std::filesystem::path out = dir / "out";
  // Only the final map is needed: no 3D scenes, no window, no intermediate map images; INFO
  // verbosity still prints one line per step. 5 particles instead of 20 keep the run short.
  testing::WriteFile(dir / "rbpf.ini", EditedIni(ReadAll(kRbpfConfig), {{"rawlog_file", rawlog.string()},
                                                                        {"logOutput_dir", out.string()},
                                                                        {"SHOW_PROGRESS_IN_WINDOW", "0"},
                                                                        {"SAVE_3D_SCENE", "0"},
                                                                        {"SAVE_MAP_IMAGES", "0"},
                                                                        {"LOG_FREQUENCY", "0"},
                                                                        {"verbosity_level", "INFO"},
                                                                        {"sampleSize", "5"}}));
  // stdin from /dev/null: on an error rbpf-slam waits for a key press.
  const std::string command =
      "cd '" + dir.path().string() + "' && timeout 300 rbpf-slam rbpf.ini < /dev/null > run.log 2>&1";
  const int status = std::system(command.c_str());
  const std::string run_log = ReadAll(dir / "run.log");
  ASSERT_EQ(status, 0) << command << "\n" << run_log.substr(run_log.size() > 3000 ? run_log.size() - 3000 : 0);

  // Every action/sensory-frame pair is one step; the count is logged after each.
  EXPECT_NE(run_log.find("STEP " + std::to_string(kRbpfScans) + " "), std::string::npos);
  EXPECT_EQ(run_log.find("STEP " + std::to_string(kRbpfScans + 1) + " "), std::string::npos);
  EXPECT_NE(run_log.find("**END**"), std::string::npos);
  // log_estimated_path.txt: one "step x y z yaw pitch roll stamp" line per step.
  EXPECT_EQ(CountLines(ReadAll(out / "log_estimated_path.txt")), kRbpfScans);

  ExpectSaneFinalMap(out, /*insertion_distance_m=*/0.5);  // the config's insertionLinDistance

  const double ate_m = RunAte(out, prefix);
  std::cout << "[ mrpt ] rbpf-slam ATE " << ate_m << " m, noisy odometry " << prefix.odometry_ate_m << " m\n";
  EXPECT_LT(ate_m, prefix.odometry_ate_m);
}

}  // namespace
}  // namespace slamsweep::evaluator
