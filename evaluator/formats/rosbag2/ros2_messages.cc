#include "evaluator/formats/rosbag2/ros2_messages.h"

#include <fmt/format.h>

#include <map>
#include <set>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/bag/bag_conversions.h"
#include "evaluator/formats/rosbag2/cdr.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {
namespace {

/// builtin_interfaces/Time.
double ReadTime(CdrReader& reader) {
  const std::int32_t sec = reader.Int32();
  const std::uint32_t nanosec = reader.Uint32();
  return RosTimeSeconds(sec, nanosec);
}

struct Header {
  double stamp_s = 0.0;
  std::string frame_id;
};

Header ReadHeader(CdrReader& reader) {
  Header header;
  header.stamp_s = ReadTime(reader);
  header.frame_id = reader.String();
  return header;
}

/// geometry_msgs/Pose (Point, Quaternion) or Transform (Vector3, Quaternion): the same seven float64.
BagPose ReadPose(CdrReader& reader) {
  BagPose pose;
  pose.x_m = reader.Float64();
  pose.y_m = reader.Float64();
  pose.z_m = reader.Float64();
  pose.qx = reader.Float64();
  pose.qy = reader.Float64();
  pose.qz = reader.Float64();
  pose.qw = reader.Float64();
  return pose;
}

constexpr std::size_t kCovarianceSize = 36;

BagStampedPose ReadTransformStamped(CdrReader& reader, double record_s) {
  BagStampedPose out;
  const Header header = ReadHeader(reader);
  out.stamp_s = header.stamp_s;
  out.record_s = record_s;
  out.frame_id = header.frame_id;
  out.child_frame_id = reader.String();
  out.pose = ReadPose(reader);
  return out;
}

void WriteTime(CdrWriter& writer, double stamp_s, std::string_view where) {
  const RosTime time = ToRosTime(stamp_s, where);
  writer.Int32(static_cast<std::int32_t>(time.sec));
  writer.Uint32(time.nanosec);
}

void WriteHeader(CdrWriter& writer, double stamp_s, const std::string& frame_id, std::string_view where) {
  WriteTime(writer, stamp_s, where);
  writer.String(frame_id);
}

void WritePose(CdrWriter& writer, const BagPose& pose) {
  for (const double value : {pose.x_m, pose.y_m, pose.z_m, pose.qx, pose.qy, pose.qz, pose.qw}) writer.Float64(value);
}

void WriteZeros(CdrWriter& writer, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) writer.Float64(0.0);
}

/// The fields of each type slamsweep writes, as the .msg files define them (without comments).
const std::map<std::string, std::string>& Definitions() {
  static const std::map<std::string, std::string> definitions = {
      {"sensor_msgs/LaserScan",
       "std_msgs/Header header\nfloat32 angle_min\nfloat32 angle_max\nfloat32 angle_increment\n"
       "float32 time_increment\nfloat32 scan_time\nfloat32 range_min\nfloat32 range_max\nfloat32[] ranges\n"
       "float32[] intensities\n"},
      {"nav_msgs/Odometry",
       "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n"
       "geometry_msgs/TwistWithCovariance twist\n"},
      {"tf2_msgs/TFMessage", "geometry_msgs/TransformStamped[] transforms\n"},
      {"std_msgs/Header", "builtin_interfaces/Time stamp\nstring frame_id\n"},
      {"builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n"},
      {"geometry_msgs/PoseWithCovariance", "geometry_msgs/Pose pose\nfloat64[36] covariance\n"},
      {"geometry_msgs/TwistWithCovariance", "geometry_msgs/Twist twist\nfloat64[36] covariance\n"},
      {"geometry_msgs/Pose", "geometry_msgs/Point position\ngeometry_msgs/Quaternion orientation\n"},
      {"geometry_msgs/Twist", "geometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n"},
      {"geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Quaternion", "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n"},
      {"geometry_msgs/TransformStamped",
       "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/Transform transform\n"},
      {"geometry_msgs/Transform", "geometry_msgs/Vector3 translation\ngeometry_msgs/Quaternion rotation\n"},
  };
  return definitions;
}

/// The types `type`'s fields use, depth first in field order, each once.
void CollectDependencies(const std::string& type, std::vector<std::string>& order, std::set<std::string>& seen) {
  const std::string& fields = Definitions().at(type);
  std::size_t start = 0;
  while (start < fields.size()) {
    const std::size_t end = fields.find('\n', start);
    std::string field_type = fields.substr(start, fields.find(' ', start) - start);
    start = end + 1;
    if (const std::size_t bracket = field_type.find('['); bracket != std::string::npos) field_type.resize(bracket);
    if (field_type.find('/') == std::string::npos || !seen.insert(field_type).second) continue;
    order.push_back(field_type);
    CollectDependencies(field_type, order, seen);
  }
}

}  // namespace

BagScan DecodeLaserScan(std::span<const std::uint8_t> cdr, double record_s, const std::string& where) {
  CdrReader reader(cdr, where);
  BagScan scan;
  const Header header = ReadHeader(reader);
  scan.stamp_s = header.stamp_s;
  scan.record_s = record_s;
  scan.frame_id = header.frame_id;
  scan.angle_min_rad = reader.Float32();
  scan.angle_max_rad = reader.Float32();
  scan.angle_increment_rad = reader.Float32();
  reader.Float32();  // time_increment
  reader.Float32();  // scan_time
  scan.range_min_m = reader.Float32();
  scan.range_max_m = reader.Float32();
  scan.ranges_m = reader.Float32Sequence();
  return scan;
}

BagStampedPose DecodeStampedPose(BagMessageKind kind, std::span<const std::uint8_t> cdr, double record_s,
                                 const std::string& where) {
  CdrReader reader(cdr, where);
  if (kind == BagMessageKind::kTransformStamped) return ReadTransformStamped(reader, record_s);
  BagStampedPose out;
  const Header header = ReadHeader(reader);
  out.stamp_s = header.stamp_s;
  out.record_s = record_s;
  out.frame_id = header.frame_id;
  switch (kind) {
    case BagMessageKind::kOdometry:
      out.child_frame_id = reader.String();
      out.pose = ReadPose(reader);
      reader.Skip(kCovarianceSize, sizeof(double));
      return out;
    case BagMessageKind::kPoseStamped:
      out.pose = ReadPose(reader);
      return out;
    case BagMessageKind::kPoseWithCovarianceStamped:
      out.pose = ReadPose(reader);
      reader.Skip(kCovarianceSize, sizeof(double));
      return out;
    default:
      break;
  }
  throw InputError(fmt::format("{}: not a stamped pose message", where));
}

void DecodeTfMessage(std::span<const std::uint8_t> cdr, double record_s, const std::string& where,
                     std::vector<BagStampedPose>& out) {
  CdrReader reader(cdr, where);
  // A TransformStamped takes at least 4 + 4 + 4 (stamp, empty frame) + 4 (empty child) + 7 * 8 bytes.
  constexpr std::size_t kMinTransformSize = 72;
  const std::uint32_t count = reader.SequenceLength(kMinTransformSize);
  for (std::uint32_t i = 0; i < count; ++i) out.push_back(ReadTransformStamped(reader, record_s));
}

std::vector<std::uint8_t> EncodeLaserScan(const BagScan& scan) {
  CdrWriter writer;
  WriteHeader(writer, scan.stamp_s, scan.frame_id, "LaserScan");
  for (const float value : {scan.angle_min_rad, scan.angle_max_rad, scan.angle_increment_rad, 0.0f, 0.0f,
                            scan.range_min_m, scan.range_max_m}) {
    writer.Float32(value);
  }
  writer.Float32Sequence(scan.ranges_m);
  writer.Float32Sequence({});
  return writer.Bytes();
}

std::vector<std::uint8_t> EncodeOdometry(const BagStampedPose& odometry) {
  CdrWriter writer;
  WriteHeader(writer, odometry.stamp_s, odometry.frame_id, "Odometry");
  writer.String(odometry.child_frame_id);
  WritePose(writer, odometry.pose);
  WriteZeros(writer, kCovarianceSize);
  WriteZeros(writer, 6 + kCovarianceSize);  // twist: linear, angular, covariance
  return writer.Bytes();
}

std::vector<std::uint8_t> EncodeTfMessage(const std::vector<BagStampedPose>& transforms) {
  CdrWriter writer;
  writer.Uint32(static_cast<std::uint32_t>(transforms.size()));
  for (const BagStampedPose& transform : transforms) {
    WriteHeader(writer, transform.stamp_s, transform.frame_id, "TFMessage");
    writer.String(transform.child_frame_id);
    WritePose(writer, transform.pose);
  }
  return writer.Bytes();
}

std::string Ros2MessageDefinition(BagMessageKind kind) {
  std::string type;
  switch (kind) {
    case BagMessageKind::kLaserScan:
      type = "sensor_msgs/LaserScan";
      break;
    case BagMessageKind::kOdometry:
      type = "nav_msgs/Odometry";
      break;
    case BagMessageKind::kTfMessage:
      type = "tf2_msgs/TFMessage";
      break;
    default:
      return "";
  }
  std::vector<std::string> dependencies;
  std::set<std::string> seen{type};
  CollectDependencies(type, dependencies, seen);
  std::string text = Definitions().at(type);
  for (const std::string& dependency : dependencies) {
    text += std::string(80, '=') + "\nMSG: " + dependency + "\n" + Definitions().at(dependency);
  }
  return text;
}

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
