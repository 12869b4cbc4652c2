#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "evaluator/formats/rosbag/bag_messages.h"
#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline formats::inline rosbag {

/// How a ROS1 bag with 2D laser scans becomes a Sequence. The defaults read a bag that has one
/// sensor_msgs/LaserScan topic and either one nav_msgs/Odometry topic or /tf odom -> base_link.
struct RosbagReadOptions {
  /// Empty: the bag's file name without ".bag".
  std::string name;
  /// sensor_msgs/LaserScan topic. Empty: the only one in the bag (an error listing them when there
  /// are several).
  std::string scan_topic;
  /// nav_msgs/Odometry topic. Empty: the only Odometry topic other than reference_topic; when the
  /// bag has none, odometry is /tf odom_frame -> base_frame (an error listing them when several).
  std::string odometry_topic;
  std::string odom_frame = "odom";
  /// The robot frame: odometry and reference poses are its poses, the laser is mounted on it.
  std::string base_frame = "base_link";
  /// Ground truth from a nav_msgs/Odometry topic (e.g. "/ground_truth"). Empty: none, unless
  /// reference_frame is set. Setting both is an error.
  std::string reference_topic;
  /// Ground truth from /tf: the pose of base_frame in this frame (e.g. "map"), at every stamp of the
  /// time-varying transforms between them.
  std::string reference_frame;
  /// The laser's frame for the mounting pose (/tf or /tf_static base_frame -> laser_frame). Empty:
  /// each scan's header.frame_id.
  std::string laser_frame;
  /// When set, used as is; otherwise the bag's path as source.
  std::optional<Provenance> provenance;
};

/// Throws InputError naming the option when options contradict each other or a frame is empty.
void CheckRosbagReadOptions(const RosbagReadOptions& options);

/// The topics of a bag, for `slamsweep data info` and for choosing topics.
struct RosbagInfo {
  std::filesystem::path bag;
  /// Sorted by topic name.
  std::vector<BagTopic> topics;
  std::size_t message_count = 0;
  /// Record time of the first and last message (0 when the bag is empty).
  double start_s = 0.0;
  double end_s = 0.0;
};

/// Lists a bag's topics, types and message counts from its index. Throws InputError naming the bag
/// when it is missing or not a ROS1 bag.
RosbagInfo InspectRosbag(const std::filesystem::path& bag);

/// Topics recorded with exactly `datatype` (e.g. kLaserScanType), sorted.
std::vector<std::string> TopicsOfType(const RosbagInfo& info, std::string_view datatype);

/// Reads a ROS1 bag (librosbag) into a Sequence:
///  - scans: the scan topic's messages ordered by header.stamp (the record time when a stamp is 0);
///    later messages with an already seen stamp are dropped. Fields map directly; NaN and +-inf
///    ranges (REP 117: no return / too close) become range_max_m, i.e. "no return".
///  - odometry: each scan gets the odometry pose interpolated at its stamp (linear position, slerp
///    orientation); scans outside the odometry's time span are dropped, with a warning counting them.
///  - sensor_pose_on_robot: /tf_static or /tf base_frame -> laser frame (a /tf mount is taken at the
///    scan's stamp, or its nearest sample); identity, with a warning, when /tf does not join them.
///  - reference: see reference_topic / reference_frame.
/// Poses are projected onto the plane (x, y, yaw): the sequences are 2D. Quaternions are normalised.
/// Throws InputError naming the bag (and topic or frames) when the bag is missing or not a bag, a
/// topic is missing, ambiguous or of another type, odometry or reference cannot be formed, no scan
/// lies within the odometry's span, or a message holds an unusable pose or scan.
Sequence ReadRosbag(const std::filesystem::path& bag, const RosbagReadOptions& options = {});

}  // namespace slamsweep::evaluator::inline formats::inline rosbag
