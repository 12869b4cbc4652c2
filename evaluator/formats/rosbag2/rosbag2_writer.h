#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "evaluator/core/input_error.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/sequence/robot_log.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {

/// The storage of a bag slamsweep writes.
enum class Rosbag2StorageKind {
  kMcap,     ///< MCAP with the ros2 profile (rosbag2's default since Iron)
  kSqlite3,  ///< sqlite3, schema version 3 (ROS 2 Humble's)
};

/// "mcap", "sqlite3".
inline std::string_view Rosbag2StorageName(Rosbag2StorageKind storage) {
  return storage == Rosbag2StorageKind::kMcap ? "mcap" : "sqlite3";
}

/// Inverse of Rosbag2StorageName; InputError naming `option` and the accepted values otherwise.
inline Rosbag2StorageKind ParseRosbag2Storage(std::string_view text, std::string_view option = "--storage") {
  for (const Rosbag2StorageKind storage : {Rosbag2StorageKind::kMcap, Rosbag2StorageKind::kSqlite3}) {
    if (text == Rosbag2StorageName(storage)) return storage;
  }
  throw InputError(std::string(option) + ": expected mcap or sqlite3, got '" + std::string(text) + "'");
}

/// Writes a robot log as a rosbag2 bag folder `folder` (created; an existing non-empty folder is an
/// error), for ROS 2 Humble and later: metadata.yaml version 5 and one split file FOLDER_0.mcap or
/// FOLDER_0.db3. Topics, all CDR with their message definitions embedded (ros2msg, as rosbag2 records
/// them):
///  - /scan sensor_msgs/msg/LaserScan, frame "laser" (a log whose scans sit on several mounts:
///    "laser_0", "laser_1", ... one per mount);
///  - /odom nav_msgs/msg/Odometry odom -> base_link: every odometry reading, each scan's pose among them;
///  - /tf tf2_msgs/msg/TFMessage: the same poses as odom -> base_link transforms;
///  - /tf_static: base_link -> laser frame(s), the scans' mounts;
///  - /ground_truth nav_msgs/msg/Odometry map -> base_link: `reference`, when given.
/// Every message's record time is its header stamp. Throws InputError naming the folder or file.
void WriteRosbag2(const RobotLog& log, const std::optional<Trajectory>& reference, const std::filesystem::path& folder,
                  Rosbag2StorageKind storage);

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
