#pragma once

#include <gmapping/gridfastslam/gridslamprocessor.h>

#include "evaluator/core/trajectory.h"
#include "evaluator/sequence/robot_log.h"

namespace slamsweep::slam::gmapping {

/// One pose per scan from the best particle's trajectory tree (TrajectoryFromKeyPoses): a scan the filter processed
/// gets its node's pose; any other scan gets the pose of the last processed scan before it moved by the odometry
/// between the two (GMapping skips scans until the robot has moved linearUpdate or turned angularUpdate). Scans before
/// the first processed one keep their odometry.
evaluator::Trajectory BestTrajectory(const GMapping::GridSlamProcessor& processor, const evaluator::RobotLog& robot);

}  // namespace slamsweep::slam::gmapping
