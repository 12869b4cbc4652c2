#include "orchestrator/adapters/roster_adapter.h"

#include "evaluator/core/input_error.h"
#include "evaluator/sequence_io/robot_log_file.h"
#include "orchestrator/adapters/output_files.h"
#include "orchestrator/adapters/stage_image.h"

namespace slamsweep::orchestrator::inline adapters {

namespace ev = slamsweep::evaluator;
namespace fs = std::filesystem;

std::string RosterParameterText(const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  return value.dump();
}

PreparedRun RosterAdapter::Prepare(const RunSpec& spec, const ev::RobotLog& robot, const RunPaths& paths) const {
  const fs::path driver = RosterDriver(algorithm_);
  fs::create_directories(paths.InputDir());
  fs::create_directories(paths.RawDir());
  const std::string input = SafeFileStem(spec.sequence.entry.name) + ".log";
  ev::WriteRobotLog(robot, paths.InputDir() / input, ev::SequenceWriteFormat::kCarmen);
  PreparedRun run;
  run.argv = {driver.string(),
              "--input",
              "../input/" + input,
              "--output-dir",
              ".",
              "--seed",
              std::to_string(spec.seed),
              "--stages",
              std::to_string(spec.evaluation.stages)};
  for (const auto& [key, value] : spec.algorithm.parameters.items()) {
    run.argv.push_back(key + "=" + RosterParameterText(value));
  }
  return run;
}

std::vector<fs::path> RosterAdapter::ProgramReads(const RunSpec& /*spec*/) const {
  return RosterProgramReads(algorithm_);
}

CollectedOutputs RosterAdapter::Collect(const RunSpec& spec, const ev::RobotLog& /*robot*/,
                                        const RunPaths& paths) const {
  CollectedOutputs outputs;
  outputs.map = ReadMapOutput(paths, paths.RawDir() / "map.yaml", "map");
  outputs.trajectory =
      ReadTrajectoryOutput(paths, paths.RawDir() / "trajectory.tum", ev::TrajectoryFormat::kTum, {}, outputs.warnings);
  if (spec.evaluation.stages == 0) return outputs;
  // stage-<scan index, 6 digits>: lexicographic order is build order.
  for (const fs::path& file : GlobFiles(paths.RawDir(), "stages/stage-*.yaml")) {
    outputs.stages.push_back(StageImage(ReadMapOutput(paths, file, "stage map")));
  }
  if (outputs.stages.empty()) outputs.warnings.push_back("no stage maps: raw/stages/stage-*.yaml missing");
  return outputs;
}

}  // namespace slamsweep::orchestrator::inline adapters
