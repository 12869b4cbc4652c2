#pragma once

// The boundary to librosbag. ROS1's generated message headers use std::allocator<void>::rebind,
// which C++20 removed, so the one file that includes them (bag_messages.cc) is compiled as C++17
// and this header holds only plain C++17 types: the rest of the reader never sees a ROS type.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

// Spelled the C++17 way: the ROS message library, which is C++17, includes this header.
namespace slamsweep::evaluator {
inline namespace formats {
inline namespace rosbag {

/// The ROS message types the reader understands, as ROS names them.
inline constexpr const char* kLaserScanType = "sensor_msgs/LaserScan";
inline constexpr const char* kOdometryType = "nav_msgs/Odometry";
inline constexpr const char* kTfMessageType = "tf2_msgs/TFMessage";

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

/// A nav_msgs/Odometry (pose part only) or one transform of a tf2_msgs/TFMessage: the pose of
/// `child_frame_id` in `frame_id`.
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
  std::string odometry_topic;
  std::string reference_topic;
  /// Read "/tf" and "/tf_static" (tf2_msgs/TFMessage) when the bag has them.
  bool read_tf = false;
};

struct BagMessages {
  /// In bag (record time) order, as are all the lists below.
  std::vector<BagScan> scans;
  std::vector<BagStampedPose> odometry;
  std::vector<BagStampedPose> reference;
  /// Transforms from "/tf".
  std::vector<BagStampedPose> tf;
  /// Transforms from "/tf_static".
  std::vector<BagStampedPose> tf_static;
};

/// The topics of a bag. Throws InputError naming the bag when it is missing or not a ROS1 bag.
BagSummary ReadBagSummary(const std::filesystem::path& bag);

/// Deserialises the requested topics. Throws InputError naming the bag (and topic) when the bag
/// is missing or unreadable, a requested topic is absent or has another type than expected
/// (LaserScan for the scan topic, Odometry for the odometry and reference topics), or a message
/// cannot be decoded.
BagMessages ReadBagMessages(const std::filesystem::path& bag, const BagRequest& request);

}  // namespace rosbag
}  // namespace formats
}  // namespace slamsweep::evaluator
