#include "evaluator/formats/rosbag2/rosbag2_writer.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/bag/bag_conversions.h"
#include "evaluator/formats/rosbag2/bag_metadata.h"
#include "evaluator/formats/rosbag2/mcap_writer.h"
#include "evaluator/formats/rosbag2/ros2_messages.h"
#include "evaluator/formats/rosbag2/sqlite_bag.h"
#include "evaluator/formats/trajectory/output_file.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {
namespace {

/// rosbag2's record of a publisher's QoS (metadata before version 9): keep last, reliable, and
/// volatile or (for /tf_static) transient local durability; unlimited deadline, lifespan and lease.
std::string QosProfile(bool transient_local) {
  constexpr const char* kInfinite = "    sec: 9223372036\n    nsec: 854775807\n";
  return fmt::format(
      "- history: 3\n  depth: 0\n  reliability: 1\n  durability: {}\n  deadline:\n{}  lifespan:\n{}  liveliness: 1\n"
      "  liveliness_lease_duration:\n{}  avoid_ros_namespace_conventions: false",
      transient_local ? 1 : 2, kInfinite, kInfinite, kInfinite);
}

/// The topics, in this order (Message::topic).
enum TopicIndex : std::size_t { kScanTopic, kOdomTopic, kTfTopicIndex, kTfStaticTopicIndex, kGroundTruthTopic };

struct Topic {
  std::string name;
  BagMessageKind kind;
  bool transient_local = false;
};

struct Message {
  std::size_t topic = 0;
  std::int64_t stamp_ns = 0;
  std::vector<std::uint8_t> data;
};

BagPose ToBagPose(const Pose& pose) {
  return BagPose{pose.position.x(),    pose.position.y(),    pose.position.z(),   pose.orientation.x(),
                 pose.orientation.y(), pose.orientation.z(), pose.orientation.w()};
}

BagStampedPose Stamped(double stamp_s, const std::string& frame, const std::string& child, const Pose& pose) {
  return BagStampedPose{stamp_s, stamp_s, frame, child, ToBagPose(pose)};
}

/// The odometry the bag carries: every reading, each scan's pose replacing a reading of its stamp.
Trajectory OdometryStream(const RobotLog& log) {
  std::map<double, Pose> poses;
  for (std::size_t i = 0; i < log.odometry_readings.size(); ++i) {
    poses[log.odometry_readings.stamps_s()[i]] = log.odometry_readings.poses()[i];
  }
  for (std::size_t i = 0; i < log.odometry.size(); ++i) poses[log.odometry.stamps_s()[i]] = log.odometry.poses()[i];
  Trajectory stream;
  for (const auto& [stamp_s, pose] : poses) stream.Add(stamp_s, pose);
  return stream;
}

/// Each distinct mount gets a frame: "laser" when there is one.
std::vector<std::string> LaserFrames(const RobotLog& log, std::vector<Pose>& mounts) {
  std::vector<std::string> frames;
  for (const LaserScan& scan : log.scans) {
    const auto same = [&](const Pose& mount) {
      return mount.position == scan.sensor_pose_on_robot.position &&
             mount.orientation.coeffs() == scan.sensor_pose_on_robot.orientation.coeffs();
    };
    const auto found = std::find_if(mounts.begin(), mounts.end(), same);
    frames.push_back(std::to_string(found - mounts.begin()));
    if (found == mounts.end()) mounts.push_back(scan.sensor_pose_on_robot);
  }
  for (std::string& frame : frames) frame = mounts.size() == 1 ? "laser" : "laser_" + frame;
  return frames;
}

std::vector<Message> Messages(const RobotLog& log, const std::optional<Trajectory>& reference,
                              const std::filesystem::path& folder) {
  std::vector<Message> messages;
  const auto stamp_ns = [&](double stamp_s) { return ToRosTime(stamp_s, folder.string()).Nanoseconds(); };
  std::vector<Pose> mounts;
  const std::vector<std::string> frames = LaserFrames(log, mounts);
  std::vector<BagStampedPose> statics;
  for (std::size_t i = 0; i < mounts.size(); ++i) {
    statics.push_back(Stamped(log.scans.front().stamp_s, "base_link",
                              mounts.size() == 1 ? "laser" : "laser_" + std::to_string(i), mounts[i]));
  }
  messages.push_back(Message{kTfStaticTopicIndex, stamp_ns(log.scans.front().stamp_s), EncodeTfMessage(statics)});
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    const LaserScan& scan = log.scans[i];
    BagScan out;
    out.stamp_s = scan.stamp_s;
    out.frame_id = frames[i];
    out.angle_min_rad = static_cast<float>(scan.angle_min_rad);
    out.angle_increment_rad = static_cast<float>(scan.angle_increment_rad);
    out.angle_max_rad =
        static_cast<float>(scan.angle_min_rad + scan.angle_increment_rad * static_cast<double>(scan.BeamCount() - 1));
    out.range_min_m = static_cast<float>(scan.range_min_m);
    out.range_max_m = static_cast<float>(scan.range_max_m);
    out.ranges_m = scan.ranges_m;
    messages.push_back(Message{kScanTopic, stamp_ns(scan.stamp_s), EncodeLaserScan(out)});
  }
  const Trajectory odometry = OdometryStream(log);
  for (std::size_t i = 0; i < odometry.size(); ++i) {
    const BagStampedPose pose = Stamped(odometry.stamps_s()[i], "odom", "base_link", odometry.poses()[i]);
    messages.push_back(Message{kOdomTopic, stamp_ns(pose.stamp_s), EncodeOdometry(pose)});
    messages.push_back(Message{kTfTopicIndex, stamp_ns(pose.stamp_s), EncodeTfMessage({pose})});
  }
  if (reference) {
    for (std::size_t i = 0; i < reference->size(); ++i) {
      const BagStampedPose pose = Stamped(reference->stamps_s()[i], "map", "base_link", reference->poses()[i]);
      messages.push_back(Message{kGroundTruthTopic, stamp_ns(pose.stamp_s), EncodeOdometry(pose)});
    }
  }
  std::stable_sort(messages.begin(), messages.end(),
                   [](const Message& a, const Message& b) { return a.stamp_ns < b.stamp_ns; });
  return messages;
}

}  // namespace

void WriteRosbag2(const RobotLog& log, const std::optional<Trajectory>& reference, const std::filesystem::path& folder,
                  Rosbag2StorageKind storage) {
  ValidateRobotLog(log);
  std::error_code error;
  if (std::filesystem::exists(folder, error) && !std::filesystem::is_empty(folder, error)) {
    throw InputError(Located(folder, 0, "exists and is not empty; a bag is written into a new folder"));
  }
  std::filesystem::create_directories(folder, error);
  if (error) throw InputError(Located(folder, 0, "cannot create the bag folder (" + error.message() + ")"));

  std::vector<Topic> topics = {{"/scan", BagMessageKind::kLaserScan},
                               {"/odom", BagMessageKind::kOdometry},
                               {"/tf", BagMessageKind::kTfMessage},
                               {"/tf_static", BagMessageKind::kTfMessage, true}};
  if (reference) topics.push_back({"/ground_truth", BagMessageKind::kOdometry});
  const std::vector<Message> messages = Messages(log, reference, folder);

  const std::string name =
      folder.filename().empty() ? folder.parent_path().filename().string() : folder.filename().string();
  const std::string file = name + (storage == Rosbag2StorageKind::kMcap ? "_0.mcap" : "_0.db3");
  Rosbag2Metadata metadata;
  metadata.version = 5;
  metadata.storage_identifier = std::string(Rosbag2StorageName(storage));
  metadata.relative_file_paths = {file};
  metadata.starting_time_ns = messages.front().stamp_ns;
  metadata.duration_ns = messages.back().stamp_ns - messages.front().stamp_ns;
  metadata.message_count = messages.size();
  std::vector<std::uint64_t> counts(topics.size(), 0);
  for (const Message& message : messages) ++counts[message.topic];
  for (std::size_t i = 0; i < topics.size(); ++i) {
    metadata.topics.push_back(Rosbag2TopicInfo{topics[i].name, Ros2TypeName(topics[i].kind), "cdr",
                                               QosProfile(topics[i].transient_local), counts[i]});
  }
  metadata.files = {Rosbag2FileInfo{file, metadata.starting_time_ns, metadata.duration_ns, metadata.message_count}};
  const std::string metadata_text = FormatRosbag2Metadata(metadata);

  if (storage == Rosbag2StorageKind::kMcap) {
    McapWriter writer(folder / file, "ros2");
    std::map<BagMessageKind, std::uint16_t> schemas;
    std::vector<std::uint16_t> channels;
    for (const Topic& topic : topics) {
      if (schemas.count(topic.kind) == 0) {
        schemas[topic.kind] = writer.AddSchema(Ros2TypeName(topic.kind), "ros2msg", Ros2MessageDefinition(topic.kind));
      }
      channels.push_back(writer.AddChannel(schemas[topic.kind], topic.name, "cdr",
                                           {{"offered_qos_profiles", QosProfile(topic.transient_local)}}));
    }
    for (const Message& message : messages) {
      writer.AddMessage(channels[message.topic], static_cast<std::uint64_t>(message.stamp_ns), message.data);
    }
    writer.Finish();
  } else {
    SqliteBagWriter writer(folder / file, "humble");
    std::vector<std::int64_t> ids;
    for (const Topic& topic : topics) {
      ids.push_back(writer.AddTopic(topic.name, Ros2TypeName(topic.kind), QosProfile(topic.transient_local)));
    }
    for (const Message& message : messages) writer.AddMessage(ids[message.topic], message.stamp_ns, message.data);
    writer.Finish(metadata.version, metadata_text);
  }
  WriteOutputFile(folder / "metadata.yaml", [&](std::ostream& out) { out << metadata_text; });
}

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
