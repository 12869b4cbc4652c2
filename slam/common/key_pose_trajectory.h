#pragma once

#include <map>

#include "evaluator/core/pose.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/sequence/robot_log.h"

namespace slamsweep::slam {

/// A key pose moved on by the odometry since its scan: key_pose * key_odometry^-1 * odometry, in the plane. What
/// a keyframe algorithm's estimate is for a scan it skipped.
evaluator::Pose MovedByOdometry(const evaluator::Pose& key_pose, const evaluator::Pose& key_odometry,
                                const evaluator::Pose& odometry);

/// One pose per scan from an algorithm's smoothed poses of some scans (a particle's trajectory
/// tree, a pose graph's nodes), keyed by the stamp of the scan each belongs to. A scan with a key
/// pose gets it; any other scan gets the last key pose before it moved by the odometry between the
/// two scans (algorithms skip scans until the robot has moved far enough). Scans before the first
/// key pose keep their odometry.
evaluator::Trajectory TrajectoryFromKeyPoses(const evaluator::RobotLog& robot,
                                             const std::map<double, evaluator::Pose>& key_poses);

}  // namespace slamsweep::slam
