#include "tests/evaluator/formats/rosbag/bag_test_writer.h"

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/String.h>
#include <tf2_msgs/TFMessage.h>

namespace slamsweep::testing {
namespace {

ros::Time Time(double seconds) { return ros::Time(seconds); }

ros::Time RecordTime(double stamp_s, double record_s) { return Time(record_s != 0.0 ? record_s : stamp_s); }

void SetPose(const evaluator::BagPose& pose, geometry_msgs::Pose& out) {
  out.position.x = pose.x_m;
  out.position.y = pose.y_m;
  out.position.z = pose.z_m;
  out.orientation.x = pose.qx;
  out.orientation.y = pose.qy;
  out.orientation.z = pose.qz;
  out.orientation.w = pose.qw;
}

}  // namespace

struct BagTestWriter::Impl {
  rosbag::Bag bag;
};

BagTestWriter::BagTestWriter(const std::filesystem::path& path) : impl_(std::make_unique<Impl>()) {
  impl_->bag.open(path.string(), rosbag::bagmode::Write);
}

BagTestWriter::~BagTestWriter() { impl_->bag.close(); }

void BagTestWriter::WriteScan(const std::string& topic, const evaluator::BagScan& scan) {
  sensor_msgs::LaserScan message;
  message.header.stamp = Time(scan.stamp_s);
  message.header.frame_id = scan.frame_id;
  message.angle_min = scan.angle_min_rad;
  message.angle_max = scan.angle_max_rad;
  message.angle_increment = scan.angle_increment_rad;
  message.range_min = scan.range_min_m;
  message.range_max = scan.range_max_m;
  message.ranges = scan.ranges_m;
  impl_->bag.write(topic, RecordTime(scan.stamp_s, scan.record_s), message);
}

void BagTestWriter::WriteOdometry(const std::string& topic, const evaluator::BagStampedPose& odometry) {
  nav_msgs::Odometry message;
  message.header.stamp = Time(odometry.stamp_s);
  message.header.frame_id = odometry.frame_id;
  message.child_frame_id = odometry.child_frame_id;
  SetPose(odometry.pose, message.pose.pose);
  impl_->bag.write(topic, RecordTime(odometry.stamp_s, odometry.record_s), message);
}

void BagTestWriter::WriteTransforms(const std::string& topic,
                                    const std::vector<evaluator::BagStampedPose>& transforms) {
  tf2_msgs::TFMessage message;
  for (const evaluator::BagStampedPose& transform : transforms) {
    geometry_msgs::TransformStamped out;
    out.header.stamp = Time(transform.stamp_s);
    out.header.frame_id = transform.frame_id;
    out.child_frame_id = transform.child_frame_id;
    out.transform.translation.x = transform.pose.x_m;
    out.transform.translation.y = transform.pose.y_m;
    out.transform.translation.z = transform.pose.z_m;
    out.transform.rotation.x = transform.pose.qx;
    out.transform.rotation.y = transform.pose.qy;
    out.transform.rotation.z = transform.pose.qz;
    out.transform.rotation.w = transform.pose.qw;
    message.transforms.push_back(out);
  }
  const double record_s = transforms.empty() ? 1.0 : transforms.front().stamp_s;
  impl_->bag.write(topic, Time(record_s > 0.0 ? record_s : 1.0), message);
}

void BagTestWriter::WriteText(const std::string& topic, double record_s, const std::string& text) {
  std_msgs::String message;
  message.data = text;
  impl_->bag.write(topic, Time(record_s), message);
}

}  // namespace slamsweep::testing
