#pragma once

// The messages of a bag as plain values, shared by the ROS 1 reader (librosbag) and the ROS 2 reader
// (rosbag2: sqlite3 and MCAP). ROS 1's generated message headers are not C++20, so the ROS 1 library
// that includes this header is compiled as C++17: everything here is plain C++17.

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

// Spelled the C++17 way: the ROS 1 message library, which is C++17, includes this header.
namespace slamsweep::evaluator {
inline namespace formats {
inline namespace bag {

/// The message types the readers understand.
enum class BagMessageKind {
  kLaserScan,                  ///< sensor_msgs/LaserScan
  kOdometry,                   ///< nav_msgs/Odometry
  kTfMessage,                  ///< tf2_msgs/TFMessage (ROS 1 tf's tf/tfMessage has the same definition)
  kPoseStamped,                ///< geometry_msgs/PoseStamped
  kPoseWithCovarianceStamped,  ///< geometry_msgs/PoseWithCovarianceStamped
  kTransformStamped,           ///< geometry_msgs/TransformStamped
  kOther,
};

/// The kind of a type as ROS 1 ("sensor_msgs/LaserScan") or ROS 2 ("sensor_msgs/msg/LaserScan") names it.
inline BagMessageKind KindOfDatatype(std::string_view datatype) {
  std::string name(datatype);
  // ROS 2 spells pkg/msg/Type; the kinds are named the ROS 1 way.
  if (const std::size_t msg = name.find("/msg/"); msg != std::string::npos) name.erase(msg, 4);
  if (name == "sensor_msgs/LaserScan") return BagMessageKind::kLaserScan;
  if (name == "nav_msgs/Odometry") return BagMessageKind::kOdometry;
  if (name == "tf2_msgs/TFMessage" || name == "tf/tfMessage") return BagMessageKind::kTfMessage;
  if (name == "geometry_msgs/PoseStamped") return BagMessageKind::kPoseStamped;
  if (name == "geometry_msgs/PoseWithCovarianceStamped") return BagMessageKind::kPoseWithCovarianceStamped;
  if (name == "geometry_msgs/TransformStamped") return BagMessageKind::kTransformStamped;
  return BagMessageKind::kOther;
}

/// The ROS 2 name of a kind ("sensor_msgs/msg/LaserScan"); "" for kOther.
inline const char* Ros2TypeName(BagMessageKind kind) {
  switch (kind) {
    case BagMessageKind::kLaserScan:
      return "sensor_msgs/msg/LaserScan";
    case BagMessageKind::kOdometry:
      return "nav_msgs/msg/Odometry";
    case BagMessageKind::kTfMessage:
      return "tf2_msgs/msg/TFMessage";
    case BagMessageKind::kPoseStamped:
      return "geometry_msgs/msg/PoseStamped";
    case BagMessageKind::kPoseWithCovarianceStamped:
      return "geometry_msgs/msg/PoseWithCovarianceStamped";
    case BagMessageKind::kTransformStamped:
      return "geometry_msgs/msg/TransformStamped";
    case BagMessageKind::kOther:
      break;
  }
  return "";
}

/// One topic of a bag. A topic recorded under several types lists them joined by ", ".
struct BagTopic {
  std::string topic;
  std::string datatype;
  std::size_t message_count = 0;
};

/// What a bag holds, from its index (no message is deserialised).
struct BagSummary {
  /// Sorted by topic name.
  std::vector<BagTopic> topics;
  std::size_t message_count = 0;
  /// Record (receive) time of the first and last message; 0 for an empty bag.
  double start_s = 0.0;
  double end_s = 0.0;
  /// What the reader noticed about the file that the user should know (a damaged index it read around).
  std::vector<std::string> notes;
};

/// A geometry_msgs pose or transform, components exactly as stored (the quaternion is not normalised).
struct BagPose {
  double x_m = 0.0;
  double y_m = 0.0;
  double z_m = 0.0;
  double qx = 0.0;
  double qy = 0.0;
  double qz = 0.0;
  double qw = 1.0;
};

/// A sensor_msgs/LaserScan, fields as stored (ranges may be NaN or +-inf).
struct BagScan {
  /// header.stamp.
  double stamp_s = 0.0;
  /// When the bag recorded the message.
  double record_s = 0.0;
  std::string frame_id;
  float angle_min_rad = 0.0f;
  float angle_max_rad = 0.0f;
  float angle_increment_rad = 0.0f;
  float range_min_m = 0.0f;
  float range_max_m = 0.0f;
  std::vector<float> ranges_m;
};

/// A stamped pose: an Odometry (its pose part), a PoseStamped, a PoseWithCovarianceStamped, or a
/// TransformStamped (alone or one of a TFMessage's): the pose of `child_frame_id` in `frame_id`
/// (child_frame_id is empty for the pose messages that have none).
struct BagStampedPose {
  double stamp_s = 0.0;
  double record_s = 0.0;
  std::string frame_id;
  std::string child_frame_id;
  BagPose pose;
};

/// Which topics to deserialise. Empty names are not read.
struct BagRequest {
  std::string scan_topic;
  /// Topics of any pose kind (Odometry, PoseStamped, PoseWithCovarianceStamped, TransformStamped).
  std::vector<std::string> pose_topics;
  /// Read "/tf" and "/tf_static" (tf2_msgs/TFMessage) when the bag has them.
  bool read_tf = false;
};

struct BagMessages {
  /// In the order the bag stores them (record time, across split files), as are all the lists below.
  std::vector<BagScan> scans;
  /// By topic, for every requested pose topic.
  std::map<std::string, std::vector<BagStampedPose>> poses;
  /// Transforms from "/tf".
  std::vector<BagStampedPose> tf;
  /// Transforms from "/tf_static".
  std::vector<BagStampedPose> tf_static;
};

/// A ROS time (sec, nanosec) in seconds. Times below 2^53 ns (104 days: stamps counted from a log's
/// start) are the correctly rounded ns / 1e9, so a stamp with at most 9 decimals reads back as the
/// double its text gives; later times (since the epoch) are sec + nanosec / 1e9.
double RosTimeSeconds(std::int64_t sec, std::uint32_t nanosec);

inline constexpr const char* kTfTopic = "/tf";
inline constexpr const char* kTfStaticTopic = "/tf_static";

}  // namespace bag
}  // namespace formats
}  // namespace slamsweep::evaluator
