#pragma once

#include "orchestrator/adapters/adapter.h"
#include "orchestrator/adapters/roster.h"

namespace slamsweep::orchestrator::inline adapters {

/// A roster algorithm run through its driver (slam/README.md, "Driver contract"), from raw/:
///   slamsweep-slam-<name> --input ../input/<seq>.log --output-dir . --seed <seed>
///                         --stages <evaluation.stages> key=value...
/// The input is the robot log as CARMEN (ODOM + FLASER, or ROBOTLASER1 for other scan fans), which
/// carries every scan's geometry. Parameters keep their upstream names; the driver refuses unknown
/// ones (a failed run naming them). Collect reads raw/trajectory.tum, raw/map.yaml and
/// raw/stages/stage-*.yaml.
class RosterAdapter : public Adapter {
 public:
  explicit RosterAdapter(const RosterAlgorithm& algorithm) : algorithm_(algorithm) {}

  PreparedRun Prepare(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
  CollectedOutputs Collect(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
  std::vector<std::filesystem::path> ProgramReads(const RunSpec& spec) const override;

 private:
  const RosterAlgorithm& algorithm_;
};

/// A parameter value as the driver's key=value text: strings as they are, booleans true/false,
/// numbers in JSON's shortest exact form.
std::string RosterParameterText(const nlohmann::json& value);

}  // namespace slamsweep::orchestrator::inline adapters
