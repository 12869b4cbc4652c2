#include "orchestrator/adapters/mrpt_adapters.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/mrpt_gridmap_format.h"
#include "evaluator/sequence/robot_log_file.h"
#include "orchestrator/adapters/output_files.h"
#include "orchestrator/adapters/rendered_map.h"
#include "orchestrator/adapters/run_failure.h"
#include "orchestrator/adapters/stage_image.h"
#include "orchestrator/config/program_path.h"
#include "orchestrator/matrix/seed_fold.h"

namespace slamsweep::orchestrator {

namespace ev = slamsweep::evaluator;
namespace fs = std::filesystem;

namespace {

constexpr const char* kApp = "MappingApplication";
constexpr const char* kPathFile = "log_estimated_path.txt";

std::string ReadTemplate(const fs::path& path, const std::string& adapter) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw ev::InputError("algorithm.adapter " + adapter + ": configuration template " + path.string() +
                         " missing (Debian: apt install mrpt-apps)");
  }
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// defaults, then the run's parameters, then the adapter's controlled keys; a parameter that
/// names a controlled key would silently lose, so it is refused.
std::vector<IniSetting> Compose(std::vector<IniSetting> defaults, const nlohmann::json& parameters,
                                const std::vector<IniSetting>& controlled) {
  std::vector<IniSetting> settings = std::move(defaults);
  for (IniSetting& setting : IniSettingsFromParameters(parameters)) {
    for (const IniSetting& fixed : controlled) {
      if (fixed.section == setting.section && fixed.key == setting.key) {
        throw ev::InputError("algorithm.parameters." + setting.section + "." + setting.key +
                             ": set by the adapter (the run folder's layout needs it), cannot be a parameter");
      }
    }
    settings.push_back(std::move(setting));
  }
  settings.insert(settings.end(), controlled.begin(), controlled.end());
  return settings;
}

std::string RawlogName(const RunSpec& spec) { return SafeFileStem(spec.sequence.entry.name) + ".rawlog"; }

/// Paths as the program sees them: it runs in raw/ (RunPaths::ProgramWorkingDir), its input is beside it.
std::string FromRawDir(const std::string& input_file) { return "../input/" + input_file; }

/// Writes input/<seq>.rawlog and input/<ini_name>; returns argv {program, ../input/<ini_name>}.
PreparedRun PrepareMrpt(const ev::RobotLog& robot, const RunPaths& paths, const std::string& rawlog_name,
                        const std::string& template_text, const std::vector<IniSetting>& settings,
                        const std::string& program, const std::string& ini_name) {
  fs::create_directories(paths.InputDir());
  fs::create_directories(paths.RawDir());
  ev::WriteRobotLog(robot, paths.InputDir() / rawlog_name, ev::SequenceWriteFormat::kRawlog);
  const fs::path ini = paths.InputDir() / ini_name;
  std::ofstream out(ini, std::ios::binary | std::ios::trunc);
  out << RenderIni(template_text, settings);
  out.close();
  if (!out) throw ev::InputError(ini.string() + ": cannot write the configuration");
  return PreparedRun{{program, FromRawDir(ini_name)}};
}

/// The final grid map and the estimated path, common to both applications.
CollectedOutputs CollectMrpt(const ev::RobotLog& robot, const RunPaths& paths, const std::string& map_png) {
  CollectedOutputs outputs;
  const fs::path image = paths.RawDir() / map_png;
  RequireOutputFile(paths, image, "map");
  RequireOutputFile(paths, ev::MrptLimitsPath(image), "map limits");
  ev::MapReadOptions map_options;
  map_options.format = ev::MapFormat::kMrptGridmap;
  outputs.map = ReadMapOutput(paths, image, "map", map_options);

  ev::TrajectoryReadOptions path_options;
  // Both apps log one line per rawlog step, and step k is scan k: the scans' stamps put the path
  // on the sequence clock (rbpf-slam's own stamps are MRPT clock values of the same instants).
  path_options.mrpt_step_stamps_s = ScanStamps(robot.scans);
  outputs.trajectory = ReadTrajectoryOutput(paths, paths.RawDir() / kPathFile, ev::TrajectoryFormat::kMrptPath,
                                            path_options, outputs.warnings);
  return outputs;
}

}  // namespace

std::vector<IniSetting> IcpSlamDefaultSettings() {
  return {
      // Why each group: see the header. Points map for matching, occupancy grid for the output map.
      {kApp, "pointsMap_count", "1"},
      {kApp, "matchAgainstTheGrid", "false"},
      {kApp, "insertionLinDistance", "0.5"},
      {kApp, "insertionAngDistance", "20"},
      // ICP thresholds of MRPT's icp-slam_demo_classic.ini, the demo that matches against points.
      {"ICP", "maxIterations", "80"},
      {"ICP", "thresholdDist", "0.3"},
      {"ICP", "thresholdAng_DEG", "5"},
      {"ICP", "ALFA", "0.8"},
      {"ICP", "smallestThresholdDist", "0.05"},
      {"ICP", "onlyUniqueRobust", "true"},
      {"ICP", "corresponding_points_decimation", "5"},
      // As MRPT's rbpf-slam intel template: rays widen with distance, so free space between diverging
      // beams is filled instead of left as grey streaks, which the enclosed-areas metric counts as
      // pockets (215 instead of 95 on intel's first 300 scans).
      {"MappingApplication_occupancyGrid_00_insertOpts", "wideningBeamsWithDistance", "1"},
  };
}

std::vector<IniSetting> IcpSlamSettings(const RunSpec& spec, const std::string& rawlog_name) {
  const std::vector<IniSetting> controlled = {
      {kApp, "rawlog_file", FromRawDir(rawlog_name)},
      {kApp, "logOutput_dir", "."},
      {kApp, "SHOW_PROGRESS_3D_REAL_TIME", "0"},
      {kApp, "SAVE_3D_SCENE", "0"},
  };
  return Compose(IcpSlamDefaultSettings(), spec.algorithm.parameters, controlled);
}

std::vector<IniSetting> RbpfSlamSettings(const RunSpec& spec, const std::string& rawlog_name, std::size_t scan_count) {
  // A map image every LOG_FREQUENCY steps: about evaluation.stages of them over the run.
  const std::size_t stages = std::max<std::size_t>(spec.evaluation.stages, 1);
  const std::size_t frequency = std::max<std::size_t>(1, (scan_count + stages - 1) / stages);
  const std::vector<IniSetting> defaults = {
      // 5 particles instead of the template's 20: a quick-start run takes seconds, not minutes.
      {kApp, "sampleSize", "5"},
      // DEBUG (the template's) writes megabytes of log per run.
      {kApp, "verbosity_level", "INFO"},
  };
  const std::vector<IniSetting> controlled = {
      {kApp, "rawlog_file", FromRawDir(rawlog_name)},
      {kApp, "logOutput_dir", "."},
      // rbpf-slam seeds MRPT's random generator from RANDOM_SEED (a negative value, its default,
      // seeds it from the clock); it reads an int, so the run's seed is folded to 31 bits.
      {kApp, "RANDOM_SEED", std::to_string(Seed31(spec.seed))},
      {kApp, "SHOW_PROGRESS_IN_WINDOW", "0"},
      {kApp, "SAVE_3D_SCENE", "0"},
      {kApp, "SAVE_MAP_IMAGES", spec.evaluation.stages > 0 ? "1" : "0"},
      {kApp, "LOG_FREQUENCY", std::to_string(frequency)},
  };
  return Compose(defaults, spec.algorithm.parameters, controlled);
}

IcpSlamAdapter::IcpSlamAdapter(fs::path template_path) : template_path_(std::move(template_path)) {}

PreparedRun IcpSlamAdapter::Prepare(const RunSpec& spec, const ev::RobotLog& robot, const RunPaths& paths) const {
  const std::string rawlog = RawlogName(spec);
  const std::vector<IniSetting> settings = IcpSlamSettings(spec, rawlog);
  return PrepareMrpt(robot, paths, rawlog, ReadTemplate(template_path_, "mrpt-icp-slam"), settings, "icp-slam",
                     "icp-slam.ini");
}

CollectedOutputs IcpSlamAdapter::Collect(const RunSpec& spec, const ev::RobotLog& robot, const RunPaths& paths) const {
  CollectedOutputs outputs = CollectMrpt(robot, paths, "_finalmaps_.txt_mrpt__maps__COccupancyGridMap2D_00.png");
  if (spec.evaluation.stages > 0) {
    try {
      outputs.stages = RenderMapFromTrajectory(robot.scans, *outputs.trajectory, spec.evaluation).stages;
    } catch (const ev::InputError& error) {
      outputs.warnings.push_back(std::string("no stage maps: ") + error.what());
    }
  }
  return outputs;
}

std::vector<fs::path> IcpSlamAdapter::ProgramFiles(const AlgorithmSpec& /*algorithm*/) const {
  return {ResolveProgram("icp-slam", fs::current_path()), template_path_};
}

Seeding IcpSlamAdapter::SeedingOf(const AlgorithmSpec& /*algorithm*/) const { return Seeding::kDeterministic; }

RbpfSlamAdapter::RbpfSlamAdapter(fs::path template_path) : template_path_(std::move(template_path)) {}

PreparedRun RbpfSlamAdapter::Prepare(const RunSpec& spec, const ev::RobotLog& robot, const RunPaths& paths) const {
  const std::string rawlog = RawlogName(spec);
  const std::vector<IniSetting> settings = RbpfSlamSettings(spec, rawlog, robot.scans.size());
  return PrepareMrpt(robot, paths, rawlog, ReadTemplate(template_path_, "mrpt-rbpf-slam"), settings, "rbpf-slam",
                     "rbpf-slam.ini");
}

CollectedOutputs RbpfSlamAdapter::Collect(const RunSpec& spec, const ev::RobotLog& robot, const RunPaths& paths) const {
  CollectedOutputs outputs = CollectMrpt(robot, paths, "finalMap_mrpt__maps__COccupancyGridMap2D_00.png");
  if (spec.evaluation.stages == 0) return outputs;
  // The zero-padded step number makes lexicographic order the build order.
  for (const fs::path& file : GlobFiles(paths.RawDir(), "maps/mapbuilt_*_COccupancyGridMap2D_00.png")) {
    ev::MapReadOptions options;
    options.format = ev::MapFormat::kMrptGridmap;
    outputs.stages.push_back(StageImage(ReadMapOutput(paths, file, "stage map", options)));
  }
  if (outputs.stages.empty()) outputs.warnings.push_back("no stage maps: raw/maps/mapbuilt_*.png missing");
  return outputs;
}

std::vector<fs::path> RbpfSlamAdapter::ProgramFiles(const AlgorithmSpec& /*algorithm*/) const {
  return {ResolveProgram("rbpf-slam", fs::current_path()), template_path_};
}

Seeding RbpfSlamAdapter::SeedingOf(const AlgorithmSpec& /*algorithm*/) const { return Seeding::kSeeded; }

}  // namespace slamsweep::orchestrator
