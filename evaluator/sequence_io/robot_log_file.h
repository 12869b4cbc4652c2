#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "evaluator/core/trajectory.h"
#include "evaluator/formats/rosbag2/rosbag2_writer.h"
#include "evaluator/sequence/robot_log.h"

namespace slamsweep::evaluator::inline sequence_io {

/// The formats slamsweep writes for SLAM programs. Every one is written from a RobotLog, so it
/// holds scans and odometry only, never a reference.
enum class SequenceWriteFormat {
  kRawlog,   ///< MRPT Actions/SensoryFrames rawlog (WriteRawlog): odometry increments and scans
  kCarmen,   ///< CARMEN log: ODOM + FLASER, or ODOM + ROBOTLASER1 when a scan is not a front-laser fan
  kTum,      ///< the odometry as a TUM trajectory (no scans)
  kRosbag2,  ///< a ROS 2 bag folder, MCAP storage (WriteRosbag2): /scan, /odom, /tf, /tf_static
};

/// "rawlog", "carmen", "tum", "rosbag2".
std::string_view SequenceWriteFormatName(SequenceWriteFormat format);
/// Inverse of SequenceWriteFormatName; InputError naming `option` and the accepted values otherwise.
SequenceWriteFormat ParseSequenceWriteFormat(std::string_view text, std::string_view option = "--to");

/// The CARMEN log text of a robot log, as a raw (uncorrected) CARMEN log holds it. First
/// "PARAM slamsweep_logged_pose odometry", then per scan, in order: an ODOM record per odometry
/// reading recorded since the previous scan (RobotLog::odometry_readings), an ODOM record (the scan's
/// odometry pose) and a laser record stamped with the scan's stamp:
///  - FLASER, when every scan has a fan that CARMEN infers from its beam count (FlaserBeamFan; also
///    when its angles are that fan's rounded to float32, as a ROS LaserScan stores them) and the
///    sensor sits at the robot origin: x y theta and odom_x odom_y odom_theta are both the odometry
///    pose. A "PARAM robot_front_laser_max" states the max range when all scans agree on it.
///  - ROBOTLASER1 otherwise, stating each scan's geometry: the robot pose is the odometry pose and
///    the laser pose is odometry * sensor pose on the robot.
/// Ranges are written as the shortest text of their float value, so they read back bit for bit.
std::string FormatCarmenLog(const RobotLog& log);

/// Writes `log` to `path` (for kRosbag2 a folder) in `format`. The log must be valid (ValidateRobotLog).
/// Throws InputError naming the path when it cannot be written, or when the build lacks MRPT for kRawlog.
void WriteRobotLog(const RobotLog& log, const std::filesystem::path& path, SequenceWriteFormat format);

/// Writes a ROS 2 bag folder (WriteRosbag2, through its format module): the robot log and, when given,
/// the reference as /ground_truth. A dataset export for ROS 2 tools, never a program's input (that is
/// WriteRobotLog's kRosbag2, without a reference). Throws InputError naming the folder.
void WriteRosbag2Folder(const RobotLog& log, const std::optional<Trajectory>& reference,
                        const std::filesystem::path& folder, Rosbag2StorageKind storage);

}  // namespace slamsweep::evaluator::inline sequence_io
