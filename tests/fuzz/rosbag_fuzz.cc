// ROS1 bags through slamsweep's bag module (slamsweep-rosbag.so, librosbag). As the rawlog target: the fuzz
// build calls the module in this process, the replay reads as slamsweep does (ReadSequence: the module in a
// child process under memory and time limits).
#include <cmath>
#include <numbers>

#include "evaluator/sequence_io/format_modules.h"
#include "evaluator/sequence_io/sequence_file.h"
#include "tests/evaluator/formats/rosbag/bag_test_writer.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/seed_data.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

namespace {

ev::BagStampedPose Planar(double stamp_s, const char* frame, const char* child, double x, double y, double yaw) {
  ev::BagStampedPose pose;
  pose.stamp_s = stamp_s;
  pose.frame_id = frame;
  pose.child_frame_id = child;
  pose.pose.x_m = x;
  pose.pose.y_m = y;
  pose.pose.qz = std::sin(yaw / 2);
  pose.pose.qw = std::cos(yaw / 2);
  return pose;
}

}  // namespace

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  const ev::RobotLog log = fuzz::SeedLog(5, 61, std::numbers::pi);
  // The simulation starts at 0 s; a bag's times start after ros::TIME_MIN, so the seeds start at 1000 s.
  constexpr double kStart_s = 1000.0;
  const std::filesystem::path odometry_bag = seeds.folder() / "odometry.bag";
  const std::filesystem::path tf_bag = seeds.folder() / "tf.bag";
  {
    slamsweep::testing::BagTestWriter with_odometry(odometry_bag);
    slamsweep::testing::BagTestWriter with_tf(tf_bag);
    with_tf.WriteTransforms("/tf_static",
                            {Planar(kStart_s + log.scans.front().stamp_s, "base_link", "laser", 0.1, 0, 0)});
    for (std::size_t i = 0; i < log.scans.size(); ++i) {
      const ev::LaserScan& scan = log.scans[i];
      ev::BagScan message;
      message.stamp_s = kStart_s + scan.stamp_s;
      message.frame_id = "laser";
      message.angle_min_rad = static_cast<float>(scan.angle_min_rad);
      message.angle_increment_rad = static_cast<float>(scan.angle_increment_rad);
      message.angle_max_rad =
          static_cast<float>(scan.angle_min_rad + scan.angle_increment_rad * (scan.ranges_m.size() - 1));
      message.range_min_m = static_cast<float>(scan.range_min_m);
      message.range_max_m = static_cast<float>(scan.range_max_m);
      message.ranges_m = scan.ranges_m;
      const ev::Pose& pose = log.odometry.poses()[i];
      const ev::BagStampedPose odometry =
          Planar(kStart_s + scan.stamp_s, "odom", "base_link", pose.position.x(), pose.position.y(), pose.Yaw());
      with_odometry.WriteScan("/scan", message);
      with_odometry.WriteOdometry("/odom", odometry);
      with_tf.WriteScan("/scan", message);
      with_tf.WriteTransforms("/tf", {odometry});
    }
    with_odometry.WriteText("/chatter", kStart_s + log.scans.front().stamp_s, "a topic the reader does not read");
  }
  for (const std::filesystem::path& bag : {odometry_bag, tf_bag}) {
    seeds.Add(bag.filename().string(), fuzz::FileBytes(bag));
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = fuzz::WriteInput("input.bag", fuzz::Bytes(data, size));
#if defined(SLAMSWEEP_FUZZING)
  fuzz::CheckSequenceRead(file, [&] {
    ev::Sequence sequence;
    ev::ThrowIfFailed(ev::LoadRosbagModule(file).read(file, ev::BagReadOptions{}, sequence));
    return sequence;
  });
#else
  fuzz::CheckSequenceRead(file, [&] { return ev::ReadSequence(file); });
#endif
  return 0;
}
