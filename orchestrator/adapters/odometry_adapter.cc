#include "orchestrator/adapters/odometry_adapter.h"

#include <string>
#include <utility>

#include "evaluator/core/input_error.h"
#include "orchestrator/adapters/rendered_map.h"

namespace slamsweep::orchestrator::inline adapters {

PreparedRun OdometryAdapter::Prepare(const RunSpec& spec, const evaluator::RobotLog& /*robot*/,
                                     const RunPaths& /*paths*/) const {
  if (!spec.algorithm.parameters.empty()) {
    throw evaluator::InputError("algorithm.parameters: the odometry adapter takes no parameters, got " +
                                spec.algorithm.parameters.dump());
  }
  return {};
}

CollectedOutputs OdometryAdapter::Collect(const RunSpec& spec, const evaluator::RobotLog& robot,
                                          const RunPaths& /*paths*/) const {
  CollectedOutputs outputs;
  outputs.trajectory = robot.odometry;
  RenderedMap rendered = RenderMapFromTrajectory(robot.scans, robot.odometry, spec.evaluation);
  outputs.map = std::move(rendered.grid);
  outputs.map_rendered_from_trajectory = true;
  outputs.stages = std::move(rendered.stages);
  return outputs;
}

}  // namespace slamsweep::orchestrator::inline adapters
