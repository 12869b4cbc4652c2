#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "orchestrator/adapters/adapter.h"
#include "orchestrator/adapters/mrpt_settings.h"

namespace slamsweep::orchestrator::inline adapters {

/// MRPT's icp-slam: `icp-slam ../input/icp-slam.ini` (run in raw/), deterministic: ICP has no random draw. Outputs:
/// raw/_finalmaps_.txt_mrpt__maps__ COccupancyGridMap2D_00.png (+ _limits.txt) and raw/log_estimated_path.txt ("step x
/// y yaw"; step k = scan k). It saves no stage maps: they are rendered from the estimated path.
class IcpSlamAdapter : public Adapter {
 public:
  explicit IcpSlamAdapter(std::filesystem::path template_path = kIcpSlamTemplate);
  PreparedRun Prepare(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
  CollectedOutputs Collect(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
  std::vector<std::filesystem::path> ProgramReads(const RunSpec& spec) const override;

 private:
  std::filesystem::path template_path_;
};

/// MRPT's rbpf-slam: `rbpf-slam ../input/rbpf-slam.ini` (run in raw/), seeded through RANDOM_SEED, 5 particles unless
/// the run says otherwise (MappingApplication.sampleSize). Outputs: raw/finalMap_mrpt__maps__COccupancyGridMap2D_00.png
/// (+ _limits.txt), raw/log_estimated_path.txt ("step x y z yaw pitch roll t") and every
/// LOG_FREQUENCY steps raw/maps/mapbuilt_NNNNN__mrpt__maps__COccupancyGridMap2D_00.png (the stages).
class RbpfSlamAdapter : public Adapter {
 public:
  explicit RbpfSlamAdapter(std::filesystem::path template_path = kRbpfSlamTemplate);
  PreparedRun Prepare(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
  CollectedOutputs Collect(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
  std::vector<std::filesystem::path> ProgramReads(const RunSpec& spec) const override;

 private:
  std::filesystem::path template_path_;
};

}  // namespace slamsweep::orchestrator::inline adapters
