#include "orchestrator/adapters/mrpt_adapters.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/mrpt_gridmap_format.h"
#include "evaluator/sequence_io/robot_log_file.h"
#include "orchestrator/adapters/output_files.h"
#include "orchestrator/adapters/rendered_map.h"
#include "orchestrator/run/run_failure.h"
#include "orchestrator/adapters/stage_image.h"
#include "orchestrator/config/program_path.h"
#include "orchestrator/matrix/seed_fold.h"

namespace slamsweep::orchestrator::inline adapters {

namespace ev = slamsweep::evaluator;
namespace fs = std::filesystem;

namespace {

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

std::string RawlogName(const RunSpec& spec) { return SafeFileStem(spec.sequence.entry.name) + ".rawlog"; }

constexpr const char* kMrptSharedData = "/usr/share/mrpt";

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

// Both applications read only their ini file and rawlog (input/); MRPT's shared data is in /usr.
std::vector<fs::path> IcpSlamAdapter::ProgramReads(const RunSpec& /*spec*/) const { return {kMrptSharedData}; }

RbpfSlamAdapter::RbpfSlamAdapter(fs::path template_path) : template_path_(std::move(template_path)) {}

PreparedRun RbpfSlamAdapter::Prepare(const RunSpec& spec, const ev::RobotLog& robot, const RunPaths& paths) const {
  const std::string rawlog = RawlogName(spec);
  const std::vector<IniSetting> settings = RbpfSlamSettings(spec, rawlog, robot.scans.size());
  return PrepareMrpt(robot, paths, rawlog, ReadTemplate(template_path_, "mrpt-rbpf-slam"), settings, "rbpf-slam",
                     "rbpf-slam.ini");
}

std::vector<fs::path> RbpfSlamAdapter::ProgramReads(const RunSpec& /*spec*/) const { return {kMrptSharedData}; }

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

}  // namespace slamsweep::orchestrator::inline adapters
