// slamsweep-slam-cartographer: Cartographer's MapBuilder with one 2D trajectory fed the scans (as
// point clouds in the robot frame) and the wheel odometry. The trajectory written is the pose
// graph's after its final optimisation; the map is its submaps painted at their optimised poses.
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>

#include <cartographer/common/time.h>
#include <cartographer/mapping/map_builder.h>
#include <cartographer/sensor/imu_data.h>
#include <cartographer/sensor/odometry_data.h>
#include <cartographer/sensor/timed_point_cloud_data.h>
#include <glog/logging.h>

#include "slam/cartographer/cartographer_map.h"
#include "slam/cartographer/cartographer_options.h"
#include "slam/common/driver_main.h"
#include "slam/common/key_pose_trajectory.h"

namespace slamsweep::slam::cartographer_driver {
namespace {

namespace carto = ::cartographer;
using SensorId = carto::mapping::TrajectoryBuilderInterface::SensorId;

constexpr char kScanSensor[] = "scan";
constexpr char kOdometrySensor[] = "odom";
constexpr char kImuSensor[] = "imu";
constexpr double kMapResolution = 0.05;

/// Cartographer's clock counts 100 ns ticks from its own epoch; a sequence's seconds are counted from
/// that epoch, and each scan's tick count is kept to find the scan again in results.
carto::common::Time ToTime(double stamp_s) {
  return carto::common::FromUniversal(0) + carto::common::FromSeconds(stamp_s);
}

carto::transform::Rigid3d Rigid(const evaluator::Pose& pose) {
  return carto::transform::Rigid3d(pose.position, pose.orientation);
}

evaluator::Pose ToPose(const carto::transform::Rigid3d& pose) {
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.translate(pose.translation());
  transform.rotate(pose.rotation());
  return evaluator::Pose::FromIsometry(transform);
}

/// The scan's beams as points in the robot frame (Cartographer's tracking frame). A no-return is
/// kept at max range: beyond max_range Cartographer inserts it as a miss of missing_data_ray_length.
carto::sensor::TimedPointCloudData ToPointCloud(const evaluator::LaserScan& scan) {
  carto::sensor::TimedPointCloudData cloud;
  cloud.time = ToTime(scan.stamp_s);
  const Eigen::Isometry3d mount = scan.sensor_pose_on_robot.ToIsometry();
  cloud.origin = mount.translation().cast<float>();
  cloud.ranges.reserve(scan.BeamCount());
  for (std::size_t b = 0; b < scan.BeamCount(); ++b) {
    double range = scan.ranges_m[b];
    if (range < scan.range_min_m) continue;
    if (!scan.IsHit(scan.ranges_m[b])) range = scan.range_max_m;
    const double angle = scan.BeamAngleRad(b);
    const Eigen::Vector3d point = mount * Eigen::Vector3d(range * std::cos(angle), range * std::sin(angle), 0.0);
    cloud.ranges.push_back({point.cast<float>(), 0.0f});
  }
  return cloud;
}

class Cartographer : public Algorithm {
 public:
  explicit Cartographer(CartographerOptions options) : options_(std::move(options)) {}

  void Run(const evaluator::RobotLog& robot, DriverOutputs& outputs) override {
    auto map_builder = carto::mapping::CreateMapBuilder(options_.map_builder);
    std::map<std::int64_t, std::size_t> scan_by_ticks;
    for (std::size_t i = 0; i < robot.scans.size(); ++i)
      scan_by_ticks[carto::common::ToUniversal(ToTime(robot.scans[i].stamp_s))] = i;
    // The local SLAM result of each scan, in the trajectory's local frame (written as the scans go,
    // so a stopped run keeps them; replaced by the optimised poses at the end).
    std::map<std::size_t, carto::transform::Rigid3d> local_poses;
    // The yaw-rate gyro below is fed only where the options ask for IMU data (Cartographer refuses it otherwise).
    const bool use_imu = options_.trajectory_builder.trajectory_builder_2d_options().use_imu_data();
    std::set<SensorId> sensors = {SensorId{SensorId::SensorType::RANGE, kScanSensor},
                                  SensorId{SensorId::SensorType::ODOMETRY, kOdometrySensor}};
    if (use_imu) sensors.insert(SensorId{SensorId::SensorType::IMU, kImuSensor});
    const int trajectory_id = map_builder->AddTrajectoryBuilder(
        sensors, options_.trajectory_builder,
        [&](int, carto::common::Time time, carto::transform::Rigid3d local_pose, carto::sensor::RangeData,
            std::unique_ptr<const carto::mapping::TrajectoryBuilderInterface::InsertionResult>) {
          const auto found = scan_by_ticks.find(carto::common::ToUniversal(time));
          if (found != scan_by_ticks.end()) local_poses[found->second] = local_pose;
        });
    carto::mapping::TrajectoryBuilderInterface* builder = map_builder->GetTrajectoryBuilder(trajectory_id);
    evaluator::Pose last = robot.odometry.poses().front();
    for (std::size_t i = 0; i < robot.scans.size(); ++i) {
      const double stamp = robot.scans[i].stamp_s;
      // Without an IMU, Cartographer's pose extrapolator turns the robot between two scans with
      // the yaw rate it knew at the earlier one: a step late, which on a log with a scan a second
      // or less apart (intel turns 0.5 rad between scans) is a different motion. A gyro that reads
      // the odometry's yaw rate over each interval, from just after the previous scan, lets it turn
      // the robot by the odometry's rotation instead. It is robot data: wheel odometry, resampled.
      const double previous = i > 0 ? robot.scans[i - 1].stamp_s : stamp - 1.0;
      const double turn =
          i > 0 ? std::remainder(robot.odometry.poses()[i].Yaw() - robot.odometry.poses()[i - 1].Yaw(), 2 * M_PI) : 0.0;
      const double interval = std::max(stamp - previous, 1e-3);
      if (use_imu) {
        builder->AddSensorData(kImuSensor, carto::sensor::ImuData{ToTime(previous + 1e-4), Eigen::Vector3d(0, 0, 9.81),
                                                                  Eigen::Vector3d(0, 0, turn / interval)});
      }
      builder->AddSensorData(kOdometrySensor,
                             carto::sensor::OdometryData{ToTime(stamp), Rigid(robot.odometry.poses()[i])});
      builder->AddSensorData(kScanSensor, ToPointCloud(robot.scans[i]));
      if (const auto found = local_poses.find(i); found != local_poses.end()) {
        const carto::transform::Rigid3d global =
            map_builder->pose_graph()->GetLocalToGlobalTransform(trajectory_id) * found->second;
        last = ToPose(global);
      }
      outputs.AddPose(i, stamp, last);
      if (outputs.StageDue(i) && i + 1 < robot.scans.size()) {
        outputs.WriteStage(i, PaintSubmaps(*map_builder->pose_graph(), kMapResolution));
      }
    }
    map_builder->FinishTrajectory(trajectory_id);
    map_builder->pose_graph()->RunFinalOptimization();

    std::map<double, evaluator::Pose> key_poses;
    for (const auto& node : map_builder->pose_graph()->GetTrajectoryNodePoses()) {
      if (node.id.trajectory_id != trajectory_id || !node.data.constant_pose_data.has_value()) continue;
      const auto found = scan_by_ticks.find(carto::common::ToUniversal(node.data.constant_pose_data->time));
      if (found == scan_by_ticks.end()) continue;
      key_poses[robot.scans[found->second].stamp_s] = ToPose(node.data.global_pose);
    }
    outputs.ReplaceTrajectory(TrajectoryFromKeyPoses(robot, key_poses));
    const evaluator::OccupancyGrid map = PaintSubmaps(*map_builder->pose_graph(), kMapResolution);
    outputs.WriteStage(robot.scans.size() - 1, map);
    outputs.WriteFinal(map);
  }

 private:
  CartographerOptions options_;
};

std::unique_ptr<Algorithm> Configure(Parameters& parameters, const DriverArgs& /*args*/,
                                     const evaluator::RobotLog& /*robot*/) {
  return std::make_unique<Cartographer>(ReadCartographerOptions(parameters));
}

}  // namespace
}  // namespace slamsweep::slam::cartographer_driver

int main(int argc, char** argv) {
  google::InitGoogleLogging(argv[0]);
  // Cartographer logs every optimisation at INFO: warnings and errors are what a run's log needs.
  FLAGS_minloglevel = google::WARNING;
  FLAGS_logtostderr = true;
  return slamsweep::slam::DriverMain(argc, argv, "slamsweep-slam-cartographer",
                                     slamsweep::slam::cartographer_driver::Configure);
}
