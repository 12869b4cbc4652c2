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

/// The settings an MRPT SLAM adapter writes into the template, in the order they are applied:
/// quick defaults, then the run's parameters, then what the adapter must control (input, output
/// folder, no windows, no 3D scenes). A run parameter naming a controlled key is an InputError.
std::vector<IniSetting> IcpSlamSettings(const RunSpec& spec, const std::string& rawlog_path);
std::vector<IniSetting> RbpfSlamSettings(const RunSpec& spec, const std::string& rawlog_path, std::size_t scan_count);

/// MRPT's icp-slam: `icp-slam input/icp-slam.ini`. Outputs: raw/_finalmaps_.txt_mrpt__maps__
/// COccupancyGridMap2D_00.png (+ _limits.txt) and raw/log_estimated_path.txt ("step x y yaw"; step k
/// = scan k). It saves no stage maps: they are rendered from the estimated path.
class IcpSlamAdapter : public Adapter {
 public:
  explicit IcpSlamAdapter(std::filesystem::path template_path = kIcpSlamTemplate);
  PreparedRun Prepare(const RunSpec& spec, const RunInputs& inputs, const RunPaths& paths) const override;
  CollectedOutputs Collect(const RunSpec& spec, const RunInputs& inputs, const RunPaths& paths) const override;

 private:
  std::filesystem::path template_path_;
};

/// MRPT's rbpf-slam: `rbpf-slam input/rbpf-slam.ini`, 5 particles unless the run says otherwise
/// (MappingApplication.sampleSize). Outputs: raw/finalMap_mrpt__maps__COccupancyGridMap2D_00.png
/// (+ _limits.txt), raw/log_estimated_path.txt ("step x y z yaw pitch roll t") and every
/// LOG_FREQUENCY steps raw/maps/mapbuilt_NNNNN__mrpt__maps__COccupancyGridMap2D_00.png (the stages).
class RbpfSlamAdapter : public Adapter {
 public:
  explicit RbpfSlamAdapter(std::filesystem::path template_path = kRbpfSlamTemplate);
  PreparedRun Prepare(const RunSpec& spec, const RunInputs& inputs, const RunPaths& paths) const override;
  CollectedOutputs Collect(const RunSpec& spec, const RunInputs& inputs, const RunPaths& paths) const override;

 private:
  std::filesystem::path template_path_;
};

}  // namespace slamsweep::orchestrator
