#include "orchestrator/adapters/mrpt_settings.h"

#include <algorithm>
#include <utility>

#include "evaluator/core/input_error.h"
#include "orchestrator/matrix/seed_fold.h"

namespace slamsweep::orchestrator::inline adapters {

namespace ev = slamsweep::evaluator;

namespace {

constexpr const char* kApp = "MappingApplication";

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

}  // namespace

std::string FromRawDir(const std::string& input_file) { return "../input/" + input_file; }

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

}  // namespace slamsweep::orchestrator::inline adapters
