#include "evaluator/formats/rosbag/rosbag_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/rosbag/bag_conversions.h"
#include "evaluator/formats/rosbag/transform_tree.h"
#include "evaluator/trajectory_metrics/interpolation.h"

namespace slamsweep::evaluator::inline formats::inline rosbag {
namespace {

std::string Join(const std::vector<std::string>& items) {
  std::string joined;
  for (const std::string& item : items) joined += (joined.empty() ? "" : ", ") + item;
  return joined;
}

std::string DescribeTopics(const RosbagInfo& info) {
  std::vector<std::string> described;
  for (const BagTopic& topic : info.topics) described.push_back(topic.topic + " (" + topic.datatype + ")");
  return described.empty() ? "the bag has no topics" : "topics in the bag: " + Join(described);
}

std::string ChooseScanTopic(const RosbagInfo& info, const RosbagReadOptions& options) {
  if (!options.scan_topic.empty()) return options.scan_topic;
  const std::vector<std::string> candidates = TopicsOfType(info, kLaserScanType);
  if (candidates.size() == 1) return candidates.front();
  if (candidates.empty())
    throw InputError(fmt::format("{}: no {} topic; {}", info.bag.string(), kLaserScanType, DescribeTopics(info)));
  throw InputError(fmt::format("{}: {} {} topics ({}); choose one with scan_topic", info.bag.string(),
                               candidates.size(), kLaserScanType, Join(candidates)));
}

/// Empty when odometry is to come from /tf.
std::string ChooseOdometryTopic(const RosbagInfo& info, const RosbagReadOptions& options) {
  if (!options.odometry_topic.empty()) return options.odometry_topic;
  std::vector<std::string> candidates = TopicsOfType(info, kOdometryType);
  std::erase(candidates, options.reference_topic);
  if (candidates.size() <= 1) return candidates.empty() ? std::string() : candidates.front();
  throw InputError(
      fmt::format("{}: {} {} topics ({}); choose the odometry with odometry_topic and the ground truth "
                  "with reference_topic",
                  info.bag.string(), candidates.size(), kOdometryType, Join(candidates)));
}

TransformTree BuildTree(const BagMessages& messages, const std::filesystem::path& bag,
                        std::vector<std::string>& warnings) {
  TransformTree tree;
  std::map<std::string, std::size_t> rejected;
  const auto add_all = [&](const std::vector<BagStampedPose>& transforms, bool is_static, const char* topic) {
    for (std::size_t i = 0; i < transforms.size(); ++i) {
      const BagStampedPose& t = transforms[i];
      const std::string where =
          fmt::format("{}: {} transform {} ({} -> {})", bag.string(), topic, i, t.frame_id, t.child_frame_id);
      const Pose pose = ToPlanarPose(t.pose, where);
      const bool added = is_static
                             ? tree.AddStatic(t.frame_id, t.child_frame_id, pose)
                             : tree.AddSample(t.frame_id, t.child_frame_id, MessageStamp(t.stamp_s, t.record_s), pose);
      if (!added) ++rejected[fmt::format("{} -> {}", CanonicalFrame(t.frame_id), CanonicalFrame(t.child_frame_id))];
    }
  };
  add_all(messages.tf_static, true, "/tf_static");
  add_all(messages.tf, false, "/tf");
  for (const auto& [edge, count] : rejected) {
    warnings.push_back(
        fmt::format("{}: ignored {} transform(s) {}: the child frame already has another parent, or "
                    "is both static and time-varying",
                    bag.string(), count, edge));
  }
  return tree;
}

Trajectory OdometryFromTf(const TransformTree& tree, const std::filesystem::path& bag,
                          const RosbagReadOptions& options) {
  Trajectory track = tree.Track(options.odom_frame, options.base_frame);
  if (track.empty()) {
    throw InputError(
        fmt::format("{}: no {} topic and no time-varying /tf from '{}' to '{}'; set odometry_topic, or "
                    "odom_frame and base_frame",
                    bag.string(), kOdometryType, options.odom_frame, options.base_frame));
  }
  return track;
}

std::optional<Trajectory> ReadReference(const BagMessages& messages, const TransformTree& tree,
                                        const std::filesystem::path& bag, const RosbagReadOptions& options,
                                        std::vector<std::string>& warnings) {
  if (!options.reference_topic.empty()) {
    std::size_t duplicates = 0;
    Trajectory reference = ToTrajectory(messages.reference, bag, options.reference_topic, duplicates);
    if (reference.empty())
      throw InputError(fmt::format("{}: reference topic '{}' has no messages", bag.string(), options.reference_topic));
    if (duplicates > 0) {
      warnings.push_back(fmt::format("{}: dropped {} reference message(s) on '{}' repeating a stamp", bag.string(),
                                     duplicates, options.reference_topic));
    }
    return reference;
  }
  if (options.reference_frame.empty()) return std::nullopt;
  Trajectory reference = tree.Track(options.reference_frame, options.base_frame);
  if (reference.empty()) {
    throw InputError(fmt::format("{}: no time-varying /tf from reference_frame '{}' to '{}'", bag.string(),
                                 options.reference_frame, options.base_frame));
  }
  return reference;
}

/// The laser's pose on the robot for one scan, cached per frame for fixed mounts.
class MountLookup {
 public:
  MountLookup(const TransformTree& tree, const std::filesystem::path& bag, const RosbagReadOptions& options)
      : tree_(tree), bag_(bag), options_(options) {}

  Pose At(const BagScan& scan, double stamp_s, std::vector<std::string>& warnings) {
    const std::string frame = CanonicalFrame(options_.laser_frame.empty() ? scan.frame_id : options_.laser_frame);
    if (frame.empty() || frame == CanonicalFrame(options_.base_frame)) return Pose();
    if (const std::optional<Pose> mount = tree_.Lookup(options_.base_frame, frame, stamp_s, /*clamp=*/true))
      return *mount;
    if (unmounted_.insert(frame).second) {
      warnings.push_back(
          fmt::format("{}: no /tf or /tf_static from '{}' to laser frame '{}'; the laser is assumed at the "
                      "robot origin",
                      bag_.string(), options_.base_frame, frame));
    }
    return Pose();
  }

 private:
  const TransformTree& tree_;
  const std::filesystem::path& bag_;
  const RosbagReadOptions& options_;
  std::set<std::string> unmounted_;
};

}  // namespace

void CheckRosbagReadOptions(const RosbagReadOptions& options) {
  if (!options.reference_topic.empty() && !options.reference_frame.empty()) {
    throw InputError(
        fmt::format("options reference_topic ('{}') and reference_frame ('{}') exclude each other; set one",
                    options.reference_topic, options.reference_frame));
  }
  if (!options.odometry_topic.empty() && options.odometry_topic == options.reference_topic) {
    throw InputError(fmt::format("options odometry_topic and reference_topic are both '{}'; expected two topics",
                                 options.odometry_topic));
  }
  if (CanonicalFrame(options.base_frame).empty())
    throw InputError("option base_frame is empty; expected a tf frame name");
  if (CanonicalFrame(options.odom_frame).empty())
    throw InputError("option odom_frame is empty; expected a tf frame name");
}

RosbagInfo InspectRosbag(const std::filesystem::path& bag) {
  BagSummary summary = ReadBagSummary(bag);
  return RosbagInfo{bag, std::move(summary.topics), summary.message_count, summary.start_s, summary.end_s};
}

std::vector<std::string> TopicsOfType(const RosbagInfo& info, std::string_view datatype) {
  std::vector<std::string> topics;
  for (const BagTopic& topic : info.topics) {
    if (topic.datatype == datatype) topics.push_back(topic.topic);
  }
  return topics;
}

Sequence ReadRosbag(const std::filesystem::path& bag, const RosbagReadOptions& options) {
  CheckRosbagReadOptions(options);
  const RosbagInfo info = InspectRosbag(bag);
  BagRequest request;
  request.scan_topic = ChooseScanTopic(info, options);
  request.odometry_topic = ChooseOdometryTopic(info, options);
  request.reference_topic = options.reference_topic;
  request.read_tf = true;
  const BagMessages messages = ReadBagMessages(bag, request);

  Sequence sequence;
  sequence.name = options.name.empty() ? bag.stem().string() : options.name;
  sequence.provenance = options.provenance.value_or(Provenance{bag.string(), "", "", ""});
  std::vector<std::string>& warnings = sequence.warnings;
  const TransformTree tree = BuildTree(messages, bag, warnings);

  std::size_t odometry_duplicates = 0;
  const Trajectory odometry = request.odometry_topic.empty()
                                  ? OdometryFromTf(tree, bag, options)
                                  : ToTrajectory(messages.odometry, bag, request.odometry_topic, odometry_duplicates);
  const std::string odometry_source = request.odometry_topic.empty()
                                          ? fmt::format("/tf {} -> {}", options.odom_frame, options.base_frame)
                                          : "topic '" + request.odometry_topic + "'";
  if (odometry.empty()) throw InputError(fmt::format("{}: odometry {} has no messages", bag.string(), odometry_source));
  if (odometry_duplicates > 0) {
    warnings.push_back(fmt::format("{}: dropped {} odometry message(s) on {} repeating a stamp", bag.string(),
                                   odometry_duplicates, odometry_source));
  }
  if (messages.scans.empty())
    throw InputError(fmt::format("{}: scan topic '{}' has no messages", bag.string(), request.scan_topic));

  std::vector<std::size_t> order(messages.scans.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto stamp = [&](std::size_t i) { return MessageStamp(messages.scans[i].stamp_s, messages.scans[i].record_s); };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return stamp(a) < stamp(b); });

  const TrajectoryInterpolator odometry_at(odometry);
  MountLookup mounts(tree, bag, options);
  std::size_t outside = 0;
  std::size_t duplicates = 0;
  for (const std::size_t i : order) {
    const BagScan& message = messages.scans[i];
    LaserScan scan = ToLaserScan(message);
    if (!sequence.scans.empty() && scan.stamp_s == sequence.scans.back().stamp_s) {
      ++duplicates;
      continue;
    }
    const std::optional<Pose> pose = odometry_at.At(scan.stamp_s);
    if (!pose) {
      ++outside;
      continue;
    }
    scan.sensor_pose_on_robot = mounts.At(message, scan.stamp_s, warnings);
    sequence.odometry.Add(scan.stamp_s, *pose);
    sequence.scans.push_back(std::move(scan));
  }
  if (duplicates > 0) {
    warnings.push_back(
        fmt::format("{}: dropped {} scan(s) on '{}' repeating a stamp", bag.string(), duplicates, request.scan_topic));
  }
  if (sequence.scans.empty()) {
    throw InputError(fmt::format("{}: none of the {} scans on '{}' lies within the time span of the odometry ({}) {}",
                                 bag.string(), messages.scans.size(), request.scan_topic, odometry_source,
                                 DescribeTimeRange(odometry)));
  }
  if (outside > 0) {
    warnings.push_back(fmt::format("{}: dropped {} of {} scans on '{}' outside the time span of the odometry ({}) {}",
                                   bag.string(), outside, messages.scans.size(), request.scan_topic, odometry_source,
                                   DescribeTimeRange(odometry)));
  }
  sequence.reference = ReadReference(messages, tree, bag, options, warnings);
  ValidateSequence(sequence);
  return sequence;
}

}  // namespace slamsweep::evaluator::inline formats::inline rosbag
