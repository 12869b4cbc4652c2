// Compiled as C++17: see ros1_bag_io.h.
#include "evaluator/formats/rosbag/ros1_bag_io.h"

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/Transform.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/exception.h>
#include <rosbag/bag.h>
#include <rosbag/exceptions.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <system_error>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
inline namespace formats {
inline namespace rosbag {

namespace {

[[noreturn]] void Fail(const std::filesystem::path& bag, const std::string& message) {
  throw InputError(bag.string() + ": " + message);
}

/// Opens the bag or explains why not. librosbag's own messages ("Error opening file", "Bag
/// unindexed") are kept after ours, since they tell a truncated bag from a foreign file.
void Open(const std::filesystem::path& path, ::rosbag::Bag& bag) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) Fail(path, "no such bag file");
  try {
    bag.open(path.string(), ::rosbag::bagmode::Read);
  } catch (const ros::Exception& e) {
    Fail(path, std::string("not a readable ROS1 bag (") + e.what() + ")");
  }
}

struct TopicIndex {
  /// Every datatype recorded on the topic and the md5 sum of its definition.
  std::map<std::string, std::string> md5_by_type;
};

std::map<std::string, TopicIndex> IndexTopics(::rosbag::View& view) {  // ::rosbag::View is not const-correct
  std::map<std::string, TopicIndex> topics;
  for (const ::rosbag::ConnectionInfo* connection : view.getConnections()) {
    topics[connection->topic].md5_by_type[connection->datatype] = connection->md5sum;
  }
  return topics;
}

std::string JoinTypes(const TopicIndex& index) {
  std::string joined;
  for (const auto& [type, md5] : index.md5_by_type) joined += (joined.empty() ? "" : ", ") + type;
  return joined;
}

std::string ListTopics(const std::map<std::string, TopicIndex>& topics) {
  if (topics.empty()) return "the bag has no topics";
  std::string list = "topics in the bag:";
  for (const auto& [topic, index] : topics) list += " " + topic + " (" + JoinTypes(index) + ")";
  return list;
}

/// The check ROS itself makes (MessageInstance::isType): the definition's md5 sum, so that a
/// message recorded under an older name with the same definition (tf/tfMessage) is accepted.
template <typename Message>
bool HasDefinitionOf(const TopicIndex& index) {
  const std::string expected_md5 = ros::message_traits::MD5Sum<Message>::value();
  for (const auto& [type, md5] : index.md5_by_type) {
    if (md5 != expected_md5) return false;
  }
  return true;
}

const TopicIndex& RequireTopic(const std::filesystem::path& bag, const std::map<std::string, TopicIndex>& topics,
                               const std::string& topic) {
  const auto found = topics.find(topic);
  if (found == topics.end()) Fail(bag, "no topic '" + topic + "'; " + ListTopics(topics));
  return found->second;
}

/// How a pose topic's messages are decoded: by the definition its connections carry.
enum class PoseDefinition { kOdometry, kPoseStamped, kPoseWithCovarianceStamped, kTransformStamped };

PoseDefinition PoseDefinitionOf(const std::filesystem::path& bag, const std::string& topic, const TopicIndex& index) {
  if (HasDefinitionOf<nav_msgs::Odometry>(index)) return PoseDefinition::kOdometry;
  if (HasDefinitionOf<geometry_msgs::PoseStamped>(index)) return PoseDefinition::kPoseStamped;
  if (HasDefinitionOf<geometry_msgs::PoseWithCovarianceStamped>(index))
    return PoseDefinition::kPoseWithCovarianceStamped;
  if (HasDefinitionOf<geometry_msgs::TransformStamped>(index)) return PoseDefinition::kTransformStamped;
  Fail(bag,
       "topic '" + topic + "' holds " + JoinTypes(index) +
           ", expected nav_msgs/Odometry, geometry_msgs/PoseStamped, PoseWithCovarianceStamped or TransformStamped");
}

template <typename Message>
void RequireDefinition(const std::filesystem::path& bag, const std::string& topic, const TopicIndex& index) {
  if (!HasDefinitionOf<Message>(index)) {
    Fail(bag, "topic '" + topic + "' holds " + JoinTypes(index) + ", expected " +
                  ros::message_traits::DataType<Message>::value());
  }
}

double Seconds(const ros::Time& time) { return RosTimeSeconds(time.sec, time.nsec); }

BagPose FromPose(const geometry_msgs::Pose& pose) {
  return BagPose{pose.position.x,    pose.position.y,    pose.position.z,   pose.orientation.x,
                 pose.orientation.y, pose.orientation.z, pose.orientation.w};
}

BagPose FromTransform(const geometry_msgs::Transform& transform) {
  return BagPose{transform.translation.x, transform.translation.y, transform.translation.z, transform.rotation.x,
                 transform.rotation.y,    transform.rotation.z,    transform.rotation.w};
}

BagScan FromScan(const sensor_msgs::LaserScan& scan, double record_s) {
  BagScan out;
  out.stamp_s = Seconds(scan.header.stamp);
  out.record_s = record_s;
  out.frame_id = scan.header.frame_id;
  out.angle_min_rad = scan.angle_min;
  out.angle_max_rad = scan.angle_max;
  out.angle_increment_rad = scan.angle_increment;
  out.range_min_m = scan.range_min;
  out.range_max_m = scan.range_max;
  out.ranges_m.assign(scan.ranges.begin(), scan.ranges.end());
  return out;
}

BagStampedPose FromOdometry(const nav_msgs::Odometry& odometry, double record_s) {
  return BagStampedPose{Seconds(odometry.header.stamp), record_s, odometry.header.frame_id, odometry.child_frame_id,
                        FromPose(odometry.pose.pose)};
}

BagStampedPose FromPoseStamped(const geometry_msgs::PoseStamped& pose, double record_s) {
  return BagStampedPose{Seconds(pose.header.stamp), record_s, pose.header.frame_id, "", FromPose(pose.pose)};
}

BagStampedPose FromPoseWithCovariance(const geometry_msgs::PoseWithCovarianceStamped& pose, double record_s) {
  return BagStampedPose{Seconds(pose.header.stamp), record_s, pose.header.frame_id, "", FromPose(pose.pose.pose)};
}

BagStampedPose FromTransformStamped(const geometry_msgs::TransformStamped& transform, double record_s) {
  return BagStampedPose{Seconds(transform.header.stamp), record_s, transform.header.frame_id, transform.child_frame_id,
                        FromTransform(transform.transform)};
}

void AppendTransforms(const tf2_msgs::TFMessage& message, double record_s, std::vector<BagStampedPose>& out) {
  for (const geometry_msgs::TransformStamped& transform : message.transforms) {
    out.push_back(FromTransformStamped(transform, record_s));
  }
}

template <typename Message>
boost::shared_ptr<Message> Instantiate(const std::filesystem::path& bag, const ::rosbag::MessageInstance& message,
                                       std::size_t index) {
  boost::shared_ptr<Message> decoded = message.instantiate<Message>();
  // RequireTopic checked every connection already; this guards against a corrupt index.
  if (!decoded) {
    Fail(bag, "message " + std::to_string(index) + " on '" + message.getTopic() + "' is " + message.getDataType() +
                  ", expected " + ros::message_traits::DataType<Message>::value());
  }
  return decoded;
}

}  // namespace

BagSummary ReadRos1BagSummary(const std::filesystem::path& path) {
  ::rosbag::Bag bag;
  Open(path, bag);
  BagSummary summary;
  try {
    ::rosbag::View all(bag);
    for (const auto& [topic, index] : IndexTopics(all)) {
      ::rosbag::View on_topic(bag, ::rosbag::TopicQuery(topic));
      summary.topics.push_back(BagTopic{topic, JoinTypes(index), on_topic.size()});
    }
    summary.message_count = all.size();
    if (summary.message_count > 0) {
      summary.start_s = Seconds(all.getBeginTime());
      summary.end_s = Seconds(all.getEndTime());
    }
  } catch (const ros::Exception& e) {
    Fail(path, std::string("cannot read the bag's index (") + e.what() + ")");
  }
  return summary;
}

BagMessages ReadRos1BagMessages(const std::filesystem::path& path, const BagRequest& request) {
  ::rosbag::Bag bag;
  Open(path, bag);
  BagMessages messages;
  std::size_t index = 0;
  std::string topic;
  try {
    ::rosbag::View index_view(bag);
    const std::map<std::string, TopicIndex> topics = IndexTopics(index_view);
    std::vector<std::string> wanted;
    if (!request.scan_topic.empty()) {
      RequireDefinition<sensor_msgs::LaserScan>(path, request.scan_topic,
                                                RequireTopic(path, topics, request.scan_topic));
      wanted.push_back(request.scan_topic);
    }
    std::map<std::string, PoseDefinition> pose_definitions;
    for (const std::string& pose_topic : request.pose_topics) {
      pose_definitions[pose_topic] = PoseDefinitionOf(path, pose_topic, RequireTopic(path, topics, pose_topic));
      messages.poses[pose_topic];
      wanted.push_back(pose_topic);
    }
    if (request.read_tf) {
      for (const char* tf_topic : {kTfTopic, kTfStaticTopic}) {
        if (topics.count(tf_topic) == 0) continue;
        RequireDefinition<tf2_msgs::TFMessage>(path, tf_topic, topics.at(tf_topic));
        wanted.push_back(tf_topic);
      }
    }
    if (wanted.empty()) return messages;

    ::rosbag::View view(bag, ::rosbag::TopicQuery(wanted));
    for (const ::rosbag::MessageInstance& message : view) {
      topic = message.getTopic();
      const double record_s = Seconds(message.getTime());
      if (topic == request.scan_topic) {
        messages.scans.push_back(FromScan(*Instantiate<sensor_msgs::LaserScan>(path, message, index), record_s));
      }
      if (const auto pose = pose_definitions.find(topic); pose != pose_definitions.end()) {
        std::vector<BagStampedPose>& out = messages.poses[topic];
        switch (pose->second) {
          case PoseDefinition::kOdometry:
            out.push_back(FromOdometry(*Instantiate<nav_msgs::Odometry>(path, message, index), record_s));
            break;
          case PoseDefinition::kPoseStamped:
            out.push_back(FromPoseStamped(*Instantiate<geometry_msgs::PoseStamped>(path, message, index), record_s));
            break;
          case PoseDefinition::kPoseWithCovarianceStamped:
            out.push_back(FromPoseWithCovariance(
                *Instantiate<geometry_msgs::PoseWithCovarianceStamped>(path, message, index), record_s));
            break;
          case PoseDefinition::kTransformStamped:
            out.push_back(
                FromTransformStamped(*Instantiate<geometry_msgs::TransformStamped>(path, message, index), record_s));
            break;
        }
      }
      if (request.read_tf && (topic == kTfTopic || topic == kTfStaticTopic)) {
        AppendTransforms(*Instantiate<tf2_msgs::TFMessage>(path, message, index), record_s,
                         topic == kTfTopic ? messages.tf : messages.tf_static);
      }
      ++index;
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    // ros::Exception for overruns; a corrupt array length can also surface as length_error or bad_alloc.
    Fail(path, "cannot decode message " + std::to_string(index) + (topic.empty() ? "" : " on '" + topic + "'") + " (" +
                   e.what() + ")");
  }
  return messages;
}

}  // namespace rosbag
}  // namespace formats
}  // namespace slamsweep::evaluator
