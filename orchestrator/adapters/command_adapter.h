#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "orchestrator/adapters/adapter.h"
#include "orchestrator/adapters/placeholder_expansion.h"

namespace slamsweep::orchestrator::inline adapters {

/// A SLAM program run through its declared argv (run_spec.h CommandDeclaration). Prepare writes
/// input/<seq>.<ext> in input_format and expands the argv. Collect reads the declared trajectory
/// (on the sequence clock; MRPT paths are stamped by step = scan) and map; without a declared map
/// the map is rendered from the trajectory and the scans. Stage maps come from stage_maps_glob,
/// else they are rendered from the trajectory when there is one.
class CommandAdapter : public Adapter {
 public:
  PreparedRun Prepare(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
  CollectedOutputs Collect(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
  std::vector<std::filesystem::path> ProgramReads(const RunSpec& spec) const override;
};

}  // namespace slamsweep::orchestrator::inline adapters
