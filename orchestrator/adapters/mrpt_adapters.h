#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "orchestrator/adapters/adapter.h"
#include "orchestrator/adapters/mrpt_ini.h"

namespace slamsweep::orchestrator {

/// The configuration templates shipped with Debian's mrpt-apps.
inline constexpr const char* kIcpSlamTemplate =
    "/usr/share/mrpt/config_files/icp-slam/icp-slam_demo_classic_gridmatch.ini";
inline constexpr const char* kRbpfSlamTemplate = "/usr/share/mrpt/config_files/rbpf-slam/gridmapping_intel.ini";

/// icp-slam's defaults on top of kIcpSlamTemplate, for laser logs like intel's (scans about 1 m and up to
/// 30 deg apart). The template was tuned for MRPT's dense demo log; on intel it diverges (11.6 m APE on
/// 300 scans) for two reasons, both measured (issue 3):
/// - icp-slam inserts a scan only after an accepted ICP match (goodness > minICPgoodnessToAccept), and
///   the template inserts only every 2 m / 45 deg. Between insertions a sparse log's scans see mostly
///   unmapped space, ICP is refused, the map stops growing and the robot never relocalises
///   (14 insertions, 267 refused matches in 300 steps). Inserting every 0.5 m / 20 deg keeps the
///   overlap high.
/// - matching against the 5 cm occupancy grid drifts in heading (-6 deg after 40 scans, 0.85 m APE
///   even when every scan is inserted); matching against a points map of the same scans, with the ICP
///   thresholds of MRPT's points-map demo (icp-slam_demo_classic.ini), keeps APE at 0.10 m. The grid
///   is still built: it is the map the adapter reports.
/// - the grid widens its rays with distance (as MRPT's rbpf-slam intel template does), so free space
///   between diverging beams is filled rather than left as faint streaks (the enclosed-areas metric
///   counts the gaps between streaks as pockets).
/// Run parameters override any of these.
std::vector<IniSetting> IcpSlamDefaultSettings();

/// The settings an MRPT SLAM adapter writes into the template, in the order they are applied:
/// quick defaults, then the run's parameters, then what the adapter must control (input, output
/// folder, no windows, no 3D scenes, rbpf-slam's RANDOM_SEED = Seed31(run seed)). A run parameter
/// naming a controlled key is an InputError. `rawlog_name` is the file name in the run's input/ folder;
/// the program runs in raw/, so the settings name "../input/<rawlog_name>" and output folder ".".
std::vector<IniSetting> IcpSlamSettings(const RunSpec& spec, const std::string& rawlog_name);
std::vector<IniSetting> RbpfSlamSettings(const RunSpec& spec, const std::string& rawlog_name, std::size_t scan_count);

/// MRPT's icp-slam: `icp-slam ../input/icp-slam.ini` (run in raw/), deterministic: ICP has no random draw. Outputs: raw/_finalmaps_.txt_mrpt__maps__
/// COccupancyGridMap2D_00.png (+ _limits.txt) and raw/log_estimated_path.txt ("step x y yaw"; step k
/// = scan k). It saves no stage maps: they are rendered from the estimated path.
class IcpSlamAdapter : public Adapter {
 public:
  explicit IcpSlamAdapter(std::filesystem::path template_path = kIcpSlamTemplate);
  PreparedRun Prepare(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
  CollectedOutputs Collect(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
  /// The program (found in PATH) and the configuration template the .ini is rendered from.
  std::vector<std::filesystem::path> ProgramFiles(const AlgorithmSpec& algorithm) const override;
  Seeding SeedingOf(const AlgorithmSpec& algorithm) const override;

 private:
  std::filesystem::path template_path_;
};

/// MRPT's rbpf-slam: `rbpf-slam ../input/rbpf-slam.ini` (run in raw/), seeded through RANDOM_SEED, 5 particles unless the run says otherwise
/// (MappingApplication.sampleSize). Outputs: raw/finalMap_mrpt__maps__COccupancyGridMap2D_00.png
/// (+ _limits.txt), raw/log_estimated_path.txt ("step x y z yaw pitch roll t") and every
/// LOG_FREQUENCY steps raw/maps/mapbuilt_NNNNN__mrpt__maps__COccupancyGridMap2D_00.png (the stages).
class RbpfSlamAdapter : public Adapter {
 public:
  explicit RbpfSlamAdapter(std::filesystem::path template_path = kRbpfSlamTemplate);
  PreparedRun Prepare(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
  CollectedOutputs Collect(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
  /// The program (found in PATH) and the configuration template the .ini is rendered from.
  std::vector<std::filesystem::path> ProgramFiles(const AlgorithmSpec& algorithm) const override;
  Seeding SeedingOf(const AlgorithmSpec& algorithm) const override;

 private:
  std::filesystem::path template_path_;
};

}  // namespace slamsweep::orchestrator
