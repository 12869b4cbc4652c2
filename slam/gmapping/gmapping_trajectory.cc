#include "slam/gmapping/gmapping_trajectory.h"

#include <map>

#include "slam/common/key_pose_trajectory.h"

namespace slamsweep::slam::gmapping {

evaluator::Trajectory BestTrajectory(const GMapping::GridSlamProcessor& processor, const evaluator::RobotLog& robot) {
  const GMapping::GridSlamProcessor::Particle& best = processor.getParticles()[processor.getBestParticleIndex()];
  std::map<double, evaluator::Pose> key_poses;  // by the stamp of the scan each node was built from
  for (const GMapping::GridSlamProcessor::TNode* node = best.node; node != nullptr; node = node->parent) {
    if (node->reading != nullptr) {
      key_poses[node->reading->getTime()] = evaluator::Pose::Planar(node->pose.x, node->pose.y, node->pose.theta);
    }
  }
  return TrajectoryFromKeyPoses(robot, key_poses);
}

}  // namespace slamsweep::slam::gmapping
