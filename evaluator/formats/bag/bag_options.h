#pragma once

#include <optional>
#include <string>

#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline formats::inline bag {

/// Which topics and frames of a bag (ROS 1 or ROS 2) make a sequence: the catalog keys of the same
/// names, an inline sequence's keys and the `data` commands' flags. Empty fields take the defaults
/// below, which read a bag with one LaserScan topic and one Odometry topic (or /tf odom -> base_link).
struct BagChoices {
  /// sensor_msgs/LaserScan topic. Empty: the only one in the bag (an error listing them when there
  /// are several).
  std::string scan_topic;
  /// nav_msgs/Odometry topic. Empty: the only Odometry topic other than reference_topic; when the
  /// bag has none, odometry is /tf odom_frame -> base_frame (an error listing them when several).
  std::string odometry_topic;
  /// Empty: "odom".
  std::string odom_frame;
  /// The robot frame: odometry and reference poses are its poses, the laser is mounted on it.
  /// Empty: "base_link".
  std::string base_frame;
  /// The laser's frame for the mounting pose (/tf_static or /tf base_frame -> laser_frame). Empty:
  /// each scan's header.frame_id.
  std::string laser_frame;
  /// A reference recorded with the data, from a topic of nav_msgs/Odometry, geometry_msgs/PoseStamped
  /// or PoseWithCovarianceStamped (e.g. "/ground_truth"). Empty: none, unless reference_frame is set.
  /// Setting both is an error.
  std::string reference_topic;
  /// A reference from /tf: the pose of base_frame in this frame (e.g. "map"), at every stamp of the
  /// time-varying transforms between them.
  std::string reference_frame;

  std::string OdomFrame() const { return odom_frame.empty() ? "odom" : odom_frame; }
  std::string BaseFrame() const { return base_frame.empty() ? "base_link" : base_frame; }
  bool HasReference() const { return !reference_topic.empty() || !reference_frame.empty(); }
  bool Empty() const { return *this == BagChoices{}; }
  bool operator==(const BagChoices&) const = default;
};

/// How a bag becomes a Sequence.
struct BagReadOptions {
  /// Empty: the bag's name (the file or folder name without its extension).
  std::string name;
  BagChoices choices;
  /// When set, used as is; otherwise the bag's path as source.
  std::optional<Provenance> provenance;
};

/// Throws InputError naming the option when options contradict each other or a frame is empty
/// after its leading '/' is dropped.
void CheckBagChoices(const BagChoices& choices);

}  // namespace slamsweep::evaluator::inline formats::inline bag
