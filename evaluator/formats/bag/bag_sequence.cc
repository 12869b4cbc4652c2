#include "evaluator/formats/bag/bag_sequence.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/bag/bag_conversions.h"
#include "evaluator/formats/bag/transform_tree.h"
#include "evaluator/trajectory_metrics/interpolation.h"

namespace slamsweep::evaluator::inline formats::inline bag {
namespace {

/// Header stamps further than this from the record times are worth a warning.
constexpr double kClockWarningS = 1.0;

std::string Join(const std::vector<std::string>& items) {
  std::string joined;
  for (const std::string& item : items) joined += (joined.empty() ? "" : ", ") + item;
  return joined;
}

std::string ChooseScanTopic(const std::filesystem::path& bag, const BagSummary& summary, const BagChoices& choices) {
  if (!choices.scan_topic.empty()) {
    RequireTopic(bag, summary, choices.scan_topic, "scan", {BagMessageKind::kLaserScan});
    return choices.scan_topic;
  }
  const std::vector<std::string> candidates = TopicsOfKind(summary, BagMessageKind::kLaserScan);
  if (candidates.size() == 1) return candidates.front();
  if (candidates.empty()) {
    throw InputError(fmt::format("{}: no sensor_msgs/LaserScan topic; {}", bag.string(), DescribeTopics(summary)));
  }
  throw InputError(fmt::format("{}: {} sensor_msgs/LaserScan topics ({}); choose one with scan_topic", bag.string(),
                               candidates.size(), Join(candidates)));
}

/// Empty when odometry is to come from /tf.
std::string ChooseOdometryTopic(const std::filesystem::path& bag, const BagSummary& summary,
                                const BagChoices& choices) {
  if (!choices.odometry_topic.empty()) {
    RequireTopic(bag, summary, choices.odometry_topic, "odometry", {BagMessageKind::kOdometry});
    return choices.odometry_topic;
  }
  std::vector<std::string> candidates = TopicsOfKind(summary, BagMessageKind::kOdometry);
  std::erase(candidates, choices.reference_topic);
  if (candidates.size() <= 1) return candidates.empty() ? std::string() : candidates.front();
  throw InputError(
      fmt::format("{}: {} nav_msgs/Odometry topics ({}); choose the odometry with odometry_topic and a reference "
                  "recorded with the data with reference_topic",
                  bag.string(), candidates.size(), Join(candidates)));
}

Trajectory OdometryFromTf(const TransformTree& tree, const std::filesystem::path& bag, const BagChoices& choices) {
  Trajectory track = tree.Track(choices.OdomFrame(), choices.BaseFrame());
  if (track.empty()) {
    throw InputError(
        fmt::format("{}: no nav_msgs/Odometry topic and no time-varying /tf from '{}' to '{}'; set odometry_topic, "
                    "or odom_frame and base_frame",
                    bag.string(), choices.OdomFrame(), choices.BaseFrame()));
  }
  return track;
}

std::optional<Trajectory> ReadReference(const BagMessages& messages, const TransformTree& tree,
                                        const std::filesystem::path& bag, const BagChoices& choices,
                                        std::vector<std::string>& warnings) {
  if (!choices.reference_topic.empty()) {
    std::size_t duplicates = 0;
    Trajectory reference =
        ToTrajectory(messages.poses.at(choices.reference_topic), bag, choices.reference_topic, duplicates);
    if (reference.empty())
      throw InputError(fmt::format("{}: reference topic '{}' has no messages", bag.string(), choices.reference_topic));
    if (duplicates > 0) {
      warnings.push_back(fmt::format("{}: dropped {} reference message(s) on '{}' repeating a stamp", bag.string(),
                                     duplicates, choices.reference_topic));
    }
    return reference;
  }
  if (choices.reference_frame.empty()) return std::nullopt;
  Trajectory reference = tree.Track(choices.reference_frame, choices.BaseFrame());
  if (reference.empty()) {
    throw InputError(fmt::format("{}: no time-varying /tf from reference_frame '{}' to '{}'", bag.string(),
                                 choices.reference_frame, choices.BaseFrame()));
  }
  return reference;
}

/// The laser's pose on the robot for one scan, cached per frame for fixed mounts.
class MountLookup {
 public:
  MountLookup(const TransformTree& tree, const std::filesystem::path& bag, const BagChoices& choices)
      : tree_(tree), bag_(bag), choices_(choices) {}

  Pose At(const BagScan& scan, double stamp_s, std::vector<std::string>& warnings) {
    const std::string frame = CanonicalFrame(choices_.laser_frame.empty() ? scan.frame_id : choices_.laser_frame);
    if (frame.empty() || frame == CanonicalFrame(choices_.BaseFrame())) return Pose();
    if (const std::optional<Pose> mount = tree_.Lookup(choices_.BaseFrame(), frame, stamp_s, /*clamp=*/true))
      return *mount;
    if (unmounted_.insert(frame).second) {
      warnings.push_back(
          fmt::format("{}: no /tf or /tf_static from '{}' to laser frame '{}'; the laser is assumed at the "
                      "robot origin",
                      bag_.string(), choices_.BaseFrame(), frame));
    }
    return Pose();
  }

 private:
  const TransformTree& tree_;
  const std::filesystem::path& bag_;
  const BagChoices& choices_;
  std::set<std::string> unmounted_;
};

/// The odometry readings with each scan's pose among them; a scan's pose replaces a reading of its stamp.
Trajectory WithScanPoses(const Trajectory& readings, const Trajectory& at_scans) {
  Trajectory merged;
  merged.Reserve(readings.size() + at_scans.size());
  std::size_t reading = 0;
  for (std::size_t scan = 0; scan < at_scans.size(); ++scan) {
    const double scan_s = at_scans.stamps_s()[scan];
    for (; reading < readings.size() && readings.stamps_s()[reading] < scan_s; ++reading) {
      merged.Add(readings.stamps_s()[reading], readings.poses()[reading]);
    }
    if (reading < readings.size() && readings.stamps_s()[reading] == scan_s) ++reading;
    merged.Add(scan_s, at_scans.poses()[scan]);
  }
  for (; reading < readings.size(); ++reading) merged.Add(readings.stamps_s()[reading], readings.poses()[reading]);
  return merged;
}

/// A warning when header stamps are not the record times: the median difference over the scans.
std::optional<std::string> ClockNote(const std::filesystem::path& bag, const std::vector<BagScan>& scans,
                                     const std::string& topic) {
  std::vector<double> differences;
  for (const BagScan& scan : scans) {
    if (scan.stamp_s != 0.0) differences.push_back(scan.record_s - scan.stamp_s);
  }
  if (differences.empty()) return std::nullopt;
  const auto middle = differences.begin() + static_cast<std::ptrdiff_t>(differences.size() / 2);
  std::nth_element(differences.begin(), middle, differences.end());
  if (std::abs(*middle) <= kClockWarningS) return std::nullopt;
  return fmt::format(
      "{}: header.stamp of '{}' differs from the bag's record time by {:.3f} s (median; e.g. a simulation clock); "
      "the sequence is timed by header.stamp, as evo reads bags",
      bag.string(), topic, *middle);
}

}  // namespace

void CheckBagChoices(const BagChoices& choices) {
  if (!choices.reference_topic.empty() && !choices.reference_frame.empty()) {
    throw InputError(
        fmt::format("options reference_topic ('{}') and reference_frame ('{}') exclude each other; set one",
                    choices.reference_topic, choices.reference_frame));
  }
  if (!choices.odometry_topic.empty() && choices.odometry_topic == choices.reference_topic) {
    throw InputError(fmt::format("options odometry_topic and reference_topic are both '{}'; expected two topics",
                                 choices.odometry_topic));
  }
  for (const auto& [name, frame] :
       {std::pair{"base_frame", choices.BaseFrame()}, {"odom_frame", choices.OdomFrame()}}) {
    if (CanonicalFrame(frame).empty())
      throw InputError(fmt::format("option {} is '{}'; expected a tf frame name", name, frame));
  }
}

Sequence ReadBagSequence(const std::filesystem::path& bag, const BagSummary& summary, const BagMessageSource& read,
                         const BagReadOptions& options) {
  const BagChoices& choices = options.choices;
  CheckBagChoices(choices);
  BagRequest request;
  request.scan_topic = ChooseScanTopic(bag, summary, choices);
  const std::string odometry_topic = ChooseOdometryTopic(bag, summary, choices);
  if (!odometry_topic.empty()) request.pose_topics.push_back(odometry_topic);
  if (!choices.reference_topic.empty()) {
    RequireTopic(bag, summary, choices.reference_topic, "reference", kReferenceKinds);
    request.pose_topics.push_back(choices.reference_topic);
  }
  request.read_tf = true;
  const BagMessages messages = read(request);

  Sequence sequence;
  sequence.name = options.name;
  sequence.provenance = options.provenance.value_or(Provenance{bag.string(), "", "", ""});
  std::vector<std::string>& warnings = sequence.warnings;
  warnings.insert(warnings.end(), summary.notes.begin(), summary.notes.end());
  const TransformTree tree = BuildTransformTree(messages, bag, warnings);

  std::size_t odometry_duplicates = 0;
  const Trajectory odometry = odometry_topic.empty() ? OdometryFromTf(tree, bag, choices)
                                                     : ToTrajectory(messages.poses.at(odometry_topic), bag,
                                                                    odometry_topic, odometry_duplicates);
  const std::string odometry_source = odometry_topic.empty()
                                          ? fmt::format("/tf {} -> {}", choices.OdomFrame(), choices.BaseFrame())
                                          : "topic '" + odometry_topic + "'";
  if (odometry.empty()) throw InputError(fmt::format("{}: odometry {} has no messages", bag.string(), odometry_source));
  if (odometry_duplicates > 0) {
    warnings.push_back(fmt::format("{}: dropped {} odometry message(s) on {} repeating a stamp", bag.string(),
                                   odometry_duplicates, odometry_source));
  }
  if (messages.scans.empty())
    throw InputError(fmt::format("{}: scan topic '{}' has no messages", bag.string(), request.scan_topic));
  if (const std::optional<std::string> note = ClockNote(bag, messages.scans, request.scan_topic))
    warnings.push_back(*note);

  std::vector<std::size_t> order(messages.scans.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto stamp = [&](std::size_t i) { return MessageStamp(messages.scans[i].stamp_s, messages.scans[i].record_s); };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return stamp(a) < stamp(b); });

  const TrajectoryInterpolator odometry_at(odometry);
  MountLookup mounts(tree, bag, choices);
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
  if (odometry.size() > sequence.scans.size()) sequence.odometry_readings = WithScanPoses(odometry, sequence.odometry);
  sequence.reference = ReadReference(messages, tree, bag, choices, warnings);
  ValidateSequence(sequence);
  return sequence;
}

}  // namespace slamsweep::evaluator::inline formats::inline bag
