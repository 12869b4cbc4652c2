#include "evaluator/formats/bag/bag_conversions.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <numeric>

#include "evaluator/core/input_error.h"
#include "evaluator/sequence/flaser_fan.h"

namespace slamsweep::evaluator::inline formats::inline bag {

Pose ToPlanarPose(const BagPose& pose, std::string_view where) {
  const double components[] = {pose.x_m, pose.y_m, pose.z_m, pose.qx, pose.qy, pose.qz, pose.qw};
  if (!std::all_of(std::begin(components), std::end(components), [](double v) { return std::isfinite(v); })) {
    throw InputError(fmt::format("{}: pose has a non-finite component", where));
  }
  Eigen::Quaterniond orientation(pose.qw, pose.qx, pose.qy, pose.qz);
  if (orientation.norm() < 1e-6) {
    throw InputError(fmt::format("{}: orientation quaternion has zero norm, expected a unit quaternion", where));
  }
  // Planar already, and unit within rounding: kept as stored (no round trip through the yaw).
  constexpr double kUnitTolerance = 1e-12;
  if (pose.z_m == 0.0 && pose.qx == 0.0 && pose.qy == 0.0 && std::abs(orientation.norm() - 1.0) < kUnitTolerance) {
    Pose planar;
    planar.position = Eigen::Vector3d(pose.x_m, pose.y_m, 0.0);
    planar.orientation = orientation;
    return planar;
  }
  orientation.normalize();
  Pose full;
  full.position = Eigen::Vector3d(pose.x_m, pose.y_m, pose.z_m);
  full.orientation = orientation;
  return Pose::Planar(pose.x_m, pose.y_m, full.Yaw());
}

double RosTimeSeconds(std::int64_t sec, std::uint32_t nanosec) {
  constexpr std::int64_t kExactNanoseconds = std::int64_t{1} << 53;
  constexpr std::int64_t kMaxExactSeconds = kExactNanoseconds / 1000000000 - 1;
  if (sec >= 0 && sec <= kMaxExactSeconds) {
    return static_cast<double>(sec * 1000000000 + nanosec) / 1e9;
  }
  return static_cast<double>(sec) + static_cast<double>(nanosec) / 1e9;
}

RosTime ToRosTime(double stamp_s, std::string_view where) {
  constexpr double kMaxSeconds = 2147483647.0;
  if (!std::isfinite(stamp_s) || stamp_s < 0.0 || stamp_s >= kMaxSeconds) {
    throw InputError(fmt::format("{}: stamp {} s cannot be a ROS time (expected 0 <= t < 2^31 s)", where, stamp_s));
  }
  RosTime time;
  time.sec = static_cast<std::int64_t>(std::floor(stamp_s));
  // stamp_s - sec is exact (Sterbenz); its nanoseconds round to the nearest.
  std::int64_t nanosec = std::llround((stamp_s - static_cast<double>(time.sec)) * 1e9);
  if (nanosec >= 1000000000) {
    ++time.sec;
    nanosec -= 1000000000;
  }
  time.nanosec = static_cast<std::uint32_t>(nanosec);
  return time;
}

LaserScan ToLaserScan(const BagScan& scan) {
  LaserScan out;
  out.stamp_s = MessageStamp(scan.stamp_s, scan.record_s);
  out.angle_min_rad = scan.angle_min_rad;
  out.angle_increment_rad = scan.angle_increment_rad;
  // A LaserScan's fan is float32: the float rounding of a fan CARMEN's SICK layouts give the beam count is
  // that fan, so a log written to a bag reads back to the log's fan (and programs get the same input).
  if (scan.ranges_m.size() >= 2) {
    const BeamFan fan = FlaserBeamFan(scan.ranges_m.size());
    if (fan.known_layout && static_cast<float>(fan.angle_min_rad) == scan.angle_min_rad &&
        static_cast<float>(fan.angle_increment_rad) == scan.angle_increment_rad) {
      out.angle_min_rad = fan.angle_min_rad;
      out.angle_increment_rad = fan.angle_increment_rad;
    }
  }
  out.range_min_m = scan.range_min_m;
  out.range_max_m = scan.range_max_m;
  out.ranges_m.reserve(scan.ranges_m.size());
  const float no_return_m = scan.range_max_m;
  for (const float range_m : scan.ranges_m) out.ranges_m.push_back(std::isfinite(range_m) ? range_m : no_return_m);
  return out;
}

Trajectory ToTrajectory(const std::vector<BagStampedPose>& poses, const std::filesystem::path& bag,
                        std::string_view topic, std::size_t& dropped_duplicates) {
  std::vector<std::size_t> order(poses.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto stamp = [&](std::size_t i) { return MessageStamp(poses[i].stamp_s, poses[i].record_s); };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return stamp(a) < stamp(b); });
  Trajectory trajectory;
  trajectory.Reserve(poses.size());
  for (const std::size_t i : order) {
    if (!trajectory.empty() && stamp(i) == trajectory.EndS()) {
      ++dropped_duplicates;
      continue;
    }
    trajectory.Add(stamp(i),
                   ToPlanarPose(poses[i].pose, fmt::format("{}: topic '{}' message {}", bag.string(), topic, i)));
  }
  return trajectory;
}

TransformTree BuildTransformTree(const BagMessages& messages, const std::filesystem::path& bag,
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
  add_all(messages.tf_static, true, kTfStaticTopic);
  add_all(messages.tf, false, kTfTopic);
  for (const auto& [edge, count] : rejected) {
    warnings.push_back(
        fmt::format("{}: ignored {} transform(s) {}: the child frame already has another parent, or "
                    "is both static and time-varying",
                    bag.string(), count, edge));
  }
  return tree;
}

}  // namespace slamsweep::evaluator::inline formats::inline bag
