#pragma once

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/pose.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/formats/bag/bag_messages.h"
#include "evaluator/formats/bag/transform_tree.h"

namespace slamsweep::evaluator::inline formats::inline bag {

/// The planar pose (x, y, yaw) of a stored pose, its quaternion normalised first (ROS tools write
/// float-rounded quaternions). A pose that is planar already (z = 0, a unit rotation about +z) keeps
/// its quaternion as stored, so that planar poses written by slamsweep read back bit for bit.
/// Throws InputError "`where`: ..." for a non-finite component or a quaternion of (near) zero norm,
/// which is no rotation at all.
Pose ToPlanarPose(const BagPose& pose, std::string_view where);

/// A ROS time: builtin_interfaces/Time (ROS 2) or ros::Time (ROS 1).
struct RosTime {
  std::int64_t sec = 0;
  std::uint32_t nanosec = 0;
  std::int64_t Nanoseconds() const { return sec * 1000000000 + nanosec; }
};

/// The ROS time of a stamp in seconds, rounded to the nanosecond: the inverse of RosTimeSeconds for
/// every stamp RosTimeSeconds returns. Throws InputError "`where`: ..." for a negative or non-finite
/// stamp, or one past 2^31 s (ROS 2's int32 seconds).
RosTime ToRosTime(double stamp_s, std::string_view where);

/// A scan's fields as they are; NaN and +-inf ranges become range_max_m (no return). The sensor
/// pose is left at identity. A fan stored as the float rounding of a CARMEN SICK layout's of its
/// beam count (FlaserBeamFan) is that layout's fan in double.
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

/// The transforms of /tf_static and /tf as a tree. Transforms tf2 would reject (a second parent, a
/// frame both static and time-varying) are ignored, with a warning per edge appended to `warnings`.
/// Errors name "`bag`: /tf transform N (PARENT -> CHILD)".
TransformTree BuildTransformTree(const BagMessages& messages, const std::filesystem::path& bag,
                                 std::vector<std::string>& warnings);

}  // namespace slamsweep::evaluator::inline formats::inline bag
