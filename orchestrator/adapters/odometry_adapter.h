#pragma once

#include "orchestrator/adapters/adapter.h"

namespace slamsweep::orchestrator::inline adapters {

/// The baseline every SLAM benchmark shows: no program, the trajectory is the run's (noisy)
/// odometry and the map is rendered from it with the scans. A SLAM program that scores worse
/// than this has made the robot's own dead reckoning worse.
class OdometryAdapter : public Adapter {
 public:
  PreparedRun Prepare(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
  CollectedOutputs Collect(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
};

}  // namespace slamsweep::orchestrator::inline adapters
