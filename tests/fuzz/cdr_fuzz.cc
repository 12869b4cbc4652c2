// The CDR decoders of the ROS 2 messages slamsweep reads. The first byte of the input picks the type (its
// value modulo 6, in the order of BagMessageKind: LaserScan, Odometry, TFMessage, PoseStamped,
// PoseWithCovarianceStamped, TransformStamped); the rest is the message as a bag stores it.
#include "evaluator/formats/rosbag2/ros2_messages.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/rosbag2_seeds.h"
#include "tests/fuzz/seed_data.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

namespace {

constexpr int kKinds = 6;
constexpr char kWhere[] = "input.cdr: topic '/fuzz' message 0";

std::string Tagged(ev::BagMessageKind kind, std::span<const std::uint8_t> message) {
  std::string input(1, static_cast<char>(kind));
  input.append(reinterpret_cast<const char*>(message.data()), message.size());
  return input;
}

ev::BagStampedPose SeedPose(double stamp_s, const char* frame, const char* child, const ev::Pose& pose) {
  ev::BagStampedPose out;
  out.stamp_s = stamp_s;
  out.record_s = stamp_s;
  out.frame_id = frame;
  out.child_frame_id = child;
  out.pose.x_m = pose.position.x();
  out.pose.y_m = pose.position.y();
  out.pose.qz = std::sin(pose.Yaw() / 2);
  out.pose.qw = std::cos(pose.Yaw() / 2);
  return out;
}

}  // namespace

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  const ev::RobotLog log = fuzz::SeedLog(3, 61, 3.0);
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    const ev::LaserScan& scan = log.scans[i];
    ev::BagScan message;
    message.stamp_s = scan.stamp_s;
    message.frame_id = "laser";
    message.angle_min_rad = static_cast<float>(scan.angle_min_rad);
    message.angle_increment_rad = static_cast<float>(scan.angle_increment_rad);
    message.range_max_m = static_cast<float>(scan.range_max_m);
    message.ranges_m = scan.ranges_m;
    const std::string index = std::to_string(i);
    seeds.Add("scan-" + index + ".cdr", Tagged(ev::BagMessageKind::kLaserScan, ev::EncodeLaserScan(message)));
    const ev::BagStampedPose odometry = SeedPose(scan.stamp_s, "odom", "base_link", log.odometry.poses()[i]);
    seeds.Add("odometry-" + index + ".cdr", Tagged(ev::BagMessageKind::kOdometry, ev::EncodeOdometry(odometry)));
    seeds.Add("tf-" + index + ".cdr",
              Tagged(ev::BagMessageKind::kTfMessage,
                     ev::EncodeTfMessage({odometry, SeedPose(scan.stamp_s, "base_link", "laser", ev::Pose())})));
  }
  // Messages of the real bags, as their recorders serialised them.
  for (const char* shared : {fuzz::kSharedMcap, fuzz::kSharedDb3}) {
    const auto file = fuzz::SharedPath(seeds, shared);
    if (!file) continue;
    std::size_t index = 0;
    for (const fuzz::SeedMessage& message : fuzz::FirstMessages(*file, 2)) {
      const ev::BagMessageKind kind = ev::KindOfDatatype(message.type);
      if (kind == ev::BagMessageKind::kOther) continue;
      seeds.Add(file->stem().string() + "-" + std::to_string(index++) + ".cdr", Tagged(kind, message.data));
    }
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const auto kind = static_cast<ev::BagMessageKind>(data[0] % kKinds);
  const std::span<const std::uint8_t> message(data + 1, size - 1);
  fuzz::ExpectReadOrInputError({"input.cdr"}, [&] {
    switch (kind) {
      case ev::BagMessageKind::kLaserScan: {
        const ev::BagScan scan = ev::DecodeLaserScan(message, 1.0, kWhere);
        fuzz::Require(scan.ranges_m.size() * sizeof(float) <= message.size(), "more ranges than the message holds");
        break;
      }
      case ev::BagMessageKind::kTfMessage: {
        std::vector<ev::BagStampedPose> transforms;
        ev::DecodeTfMessage(message, 1.0, kWhere, transforms);
        fuzz::Require(transforms.size() * 56 <= message.size(), "more transforms than the message holds");
        break;
      }
      default:
        ev::DecodeStampedPose(kind, message, 1.0, kWhere);
    }
  });
  return 0;
}
