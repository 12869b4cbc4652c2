#include "slam/common/key_pose_trajectory.h"

#include <cmath>

namespace slamsweep::slam {
namespace {

struct Pose2 {
  double x = 0, y = 0, theta = 0;
};

Pose2 Of(const evaluator::Pose& pose) { return {pose.position.x(), pose.position.y(), pose.Yaw()}; }

/// a^-1 * b
Pose2 Between(const Pose2& a, const Pose2& b) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  const double dx = b.x - a.x, dy = b.y - a.y;
  return {c * dx + s * dy, -s * dx + c * dy, std::remainder(b.theta - a.theta, 2 * M_PI)};
}

/// a * d
Pose2 Compose(const Pose2& a, const Pose2& d) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  return {a.x + c * d.x - s * d.y, a.y + s * d.x + c * d.y, std::remainder(a.theta + d.theta, 2 * M_PI)};
}

}  // namespace

evaluator::Pose MovedByOdometry(const evaluator::Pose& key_pose, const evaluator::Pose& key_odometry,
                                const evaluator::Pose& odometry) {
  const Pose2 moved = Compose(Of(key_pose), Between(Of(key_odometry), Of(odometry)));
  return evaluator::Pose::Planar(moved.x, moved.y, moved.theta);
}

evaluator::Trajectory TrajectoryFromKeyPoses(const evaluator::RobotLog& robot,
                                             const std::map<double, evaluator::Pose>& key_poses) {
  evaluator::Trajectory trajectory;
  trajectory.Reserve(robot.scans.size());
  bool have_anchor = false;
  Pose2 anchor_pose, anchor_odometry;
  for (std::size_t i = 0; i < robot.scans.size(); ++i) {
    const double stamp = robot.scans[i].stamp_s;
    const Pose2 odometry = Of(robot.odometry.poses()[i]);
    Pose2 pose = odometry;
    if (const auto found = key_poses.find(stamp); found != key_poses.end()) {
      pose = Of(found->second);
      anchor_pose = pose;
      anchor_odometry = odometry;
      have_anchor = true;
    } else if (have_anchor) {
      pose = Compose(anchor_pose, Between(anchor_odometry, odometry));
    }
    trajectory.Add(stamp, evaluator::Pose::Planar(pose.x, pose.y, pose.theta));
  }
  return trajectory;
}

}  // namespace slamsweep::slam
