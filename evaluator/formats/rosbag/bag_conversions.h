#pragma once

#include <cmath>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/pose.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/formats/rosbag/bag_messages.h"

namespace slamsweep::evaluator::inline formats::inline rosbag {

/// The planar pose (x, y, yaw) of a stored pose, its quaternion normalised first (ROS tools write
/// float-rounded quaternions). Throws InputError "`where`: ..." for a non-finite component or a
/// quaternion of (near) zero norm, which is no rotation at all.
Pose ToPlanarPose(const BagPose& pose, std::string_view where);

/// A scan's fields as they are; NaN and +-inf ranges become range_max_m (no return). The sensor
/// pose is left at identity.
LaserScan ToLaserScan(const BagScan& scan);

/// The stamp a message is placed at: header.stamp, or the record time when the header has none (0).
inline double MessageStamp(double header_stamp_s, double record_s) {
  return header_stamp_s == 0.0 ? record_s : header_stamp_s;
}

/// Stamped poses (Odometry messages) as a trajectory ordered by MessageStamp; a later message with an
/// already seen stamp is dropped and counted in `dropped_duplicates`. Errors name
/// "`bag`: topic '`topic`' message N".
Trajectory ToTrajectory(const std::vector<BagStampedPose>& poses, const std::filesystem::path& bag,
                        std::string_view topic, std::size_t& dropped_duplicates);

}  // namespace slamsweep::evaluator::inline formats::inline rosbag
