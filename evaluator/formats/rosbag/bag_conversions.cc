#include "evaluator/formats/rosbag/bag_conversions.h"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline rosbag {

Pose ToPlanarPose(const BagPose& pose, std::string_view where) {
  const double components[] = {pose.x_m, pose.y_m, pose.z_m, pose.qx, pose.qy, pose.qz, pose.qw};
  if (!std::all_of(std::begin(components), std::end(components), [](double v) { return std::isfinite(v); })) {
    throw InputError(fmt::format("{}: pose has a non-finite component", where));
  }
  Eigen::Quaterniond orientation(pose.qw, pose.qx, pose.qy, pose.qz);
  if (orientation.norm() < 1e-6) {
    throw InputError(fmt::format("{}: orientation quaternion has zero norm, expected a unit quaternion", where));
  }
  orientation.normalize();
  Pose full;
  full.position = Eigen::Vector3d(pose.x_m, pose.y_m, pose.z_m);
  full.orientation = orientation;
  return Pose::Planar(pose.x_m, pose.y_m, full.Yaw());
}

LaserScan ToLaserScan(const BagScan& scan) {
  LaserScan out;
  out.stamp_s = MessageStamp(scan.stamp_s, scan.record_s);
  out.angle_min_rad = scan.angle_min_rad;
  out.angle_increment_rad = scan.angle_increment_rad;
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

}  // namespace slamsweep::evaluator::inline formats::inline rosbag
