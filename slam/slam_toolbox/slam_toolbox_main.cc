// slamsweep-slam-slam-toolbox: slam_toolbox's Karto Mapper with slam_toolbox's Ceres solver, run the way its
// offline node runs them (the synchronous node with config/mapper_params_offline.yaml): the laser registered from
// the scan's geometry, the node's scan filter before the Mapper, every scan it passes processed in order. The
// trajectory is the processed scans' corrected poses after the last loop closure (odometry between them); the
// map is Karto's occupancy grid of the processed scans. Deterministic: Ceres and TBB run on one thread.
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <string>

#include <sys/resource.h>

#include <oneapi/tbb/global_control.h>
#include <karto_sdk/Mapper.h>
#include <solvers/ceres_solver.hpp>

#include "evaluator/core/input_error.h"
#include "slam/common/driver_main.h"
#include "slam/common/key_pose_trajectory.h"
#include "slam/slam_toolbox/node_scan_filter.h"
#include "slam/slam_toolbox/slam_toolbox_map.h"
#include "slam/slam_toolbox/slam_toolbox_options.h"

namespace slamsweep::slam::slam_toolbox_driver {
namespace {

karto::Pose2 KartoPose(const evaluator::Pose& pose) {
  return karto::Pose2(pose.position.x(), pose.position.y(), pose.Yaw());
}

evaluator::Pose ToPose(const karto::Pose2& pose) {
  return evaluator::Pose::Planar(pose.GetX(), pose.GetY(), pose.GetHeading());
}

/// The node's laser (LaserAssistant::makeLaser) from a scan's own geometry: its mount on the robot, range
/// limits, first and last beam angle and increment, and the range threshold max_laser_range, at most the
/// scan's maximum range (all of it when max_laser_range <= 0).
karto::LaserRangeFinder* MakeLaser(const evaluator::LaserScan& scan, double max_laser_range_m) {
  karto::LaserRangeFinder* laser = karto::LaserRangeFinder::CreateLaserRangeFinder(
      karto::LaserRangeFinder_Custom, karto::Name("Custom Described Lidar"));
  const evaluator::Pose& mount = scan.sensor_pose_on_robot;
  laser->SetOffsetPose(karto::Pose2(mount.position.x(), mount.position.y(), mount.Yaw()));
  laser->SetMinimumRange(scan.range_min_m);
  laser->SetMaximumRange(scan.range_max_m);
  const double angle_max = scan.BeamAngleRad(scan.BeamCount() - 1);
  laser->SetMinimumAngle(scan.angle_min_rad);
  laser->SetMaximumAngle(angle_max);
  laser->SetAngularResolution(scan.angle_increment_rad);
  // The node's 360-degree test, in the float arithmetic it does it in: a scan whose beams span the whole circle
  // with its last beam one increment short of the first again.
  const float span = static_cast<float>(std::fabs(angle_max - scan.angle_min_rad));
  const float increment = static_cast<float>(scan.angle_increment_rad);
  bool is_360 = std::fabs(span - 2.0 * M_PI) < (increment - std::numeric_limits<float>::epsilon() * 2.0f * M_PI);
  if (span > 6.10865 && std::round(span / increment) + 1 == static_cast<double>(scan.BeamCount())) is_360 = false;
  laser->SetIs360Laser(is_360);
  double threshold = max_laser_range_m;
  if (threshold <= 0 || threshold > scan.range_max_m) threshold = scan.range_max_m;
  laser->SetRangeThreshold(threshold);
  return laser;
}

/// Whether `scan` has the geometry of the scan the laser was registered from.
bool SameLaser(const evaluator::LaserScan& scan, const evaluator::LaserScan& first) {
  return scan.BeamCount() == first.BeamCount() && scan.angle_min_rad == first.angle_min_rad &&
         scan.angle_increment_rad == first.angle_increment_rad && scan.range_min_m == first.range_min_m &&
         scan.range_max_m == first.range_max_m &&
         scan.sensor_pose_on_robot.position == first.sensor_pose_on_robot.position &&
         scan.sensor_pose_on_robot.Yaw() == first.sensor_pose_on_robot.Yaw();
}

/// Counts the Mapper's loop closures, for the run's log.
class LoopClosureCounter : public karto::MapperLoopClosureListener {
 public:
  void EndLoopClosure(const std::string& /*info*/) override { ++closures; }
  int closures = 0;
};

class SlamToolbox : public Algorithm {
 public:
  explicit SlamToolbox(SlamToolboxOptions options) : options_(std::move(options)) {}

  void Run(const evaluator::RobotLog& robot, DriverOutputs& outputs) override {
    // Karto's scan matcher spreads its search over TBB's threads: one thread, like every roster driver.
    const oneapi::tbb::global_control one_thread(oneapi::tbb::global_control::max_allowed_parallelism, 1);
    RaiseStackLimit();

    // Destroyed in reverse order: the Mapper, then the solver it uses, then the dataset that owns the laser and
    // the processed scans (as in the node).
    auto dataset = std::make_unique<karto::Dataset>();
    const evaluator::LaserScan& first = robot.scans.front();
    karto::LaserRangeFinder* laser = MakeLaser(first, options_.max_laser_range_m);
    dataset->Add(laser, true);

    std::map<std::string, rclcpp::ParameterValue> node_parameters;
    for (const auto& [name, value] : options_.solver_parameters) node_parameters.emplace(name, value);
    auto node = std::make_shared<rclcpp_lifecycle::LifecycleNode>("slam_toolbox", std::move(node_parameters));
    node->declare_parameter("debug_logging", rclcpp::ParameterValue(false));  // the node declares it first
    auto solver = std::make_unique<solver_plugins::CeresSolver>();
    solver->Configure(node);

    auto mapper = std::make_unique<karto::Mapper>();
    for (const auto& apply : options_.mapper_settings) apply(*mapper);
    mapper->SetScanSolver(solver.get());
    LoopClosureCounter loop_closures;
    mapper->AddListener(&loop_closures);

    NodeScanFilter filter(options_.minimum_travel_distance, options_.minimum_time_interval_s, options_.throttle_scans);
    const karto::LocalizedRangeScan* last = nullptr;
    std::size_t passed = 0, processed = 0;
    for (std::size_t i = 0; i < robot.scans.size(); ++i) {
      const evaluator::LaserScan& scan = robot.scans[i];
      if (!SameLaser(scan, first)) {
        throw std::runtime_error("scan " + std::to_string(i) +
                                 " has another laser geometry than the first scan (beams, angles, ranges or mount): "
                                 "the driver registers one laser");
      }
      const karto::Pose2 odometry = KartoPose(robot.odometry.poses()[i]);
      if (filter.Pass(scan.stamp_s, odometry.GetX(), odometry.GetY())) {
        ++passed;
        auto range_scan = std::make_unique<karto::LocalizedRangeScan>(
            laser->GetName(), karto::RangeReadingsVector(scan.ranges_m.begin(), scan.ranges_m.end()));
        range_scan->SetOdometricPose(odometry);
        range_scan->SetCorrectedPose(odometry);
        range_scan->SetTime(scan.stamp_s);
        karto::Matrix3 covariance;
        covariance.SetToIdentity();
        if (mapper->Process(range_scan.get(), &covariance)) {
          last = range_scan.get();
          dataset->Add(range_scan.release());
          ++processed;
        }
      }
      // The last processed scan's corrected pose, moved on by the odometry since (the Mapper's own prediction).
      const karto::Pose2 pose =
          last != nullptr ? karto::Transform(last->GetOdometricPose(), last->GetCorrectedPose()).TransformPose(odometry)
                          : odometry;
      outputs.AddPose(i, scan.stamp_s, ToPose(pose));
      if (outputs.StageDue(i) && i + 1 < robot.scans.size()) {
        outputs.WriteStage(i, KartoMap(mapper->GetAllProcessedScans(), options_.resolution_m));
      }
    }

    const karto::LocalizedRangeScanVector scans = mapper->GetAllProcessedScans();
    std::map<double, evaluator::Pose> key_poses;
    for (const karto::LocalizedRangeScan* scan : scans) key_poses[scan->GetTime()] = ToPose(scan->GetCorrectedPose());
    outputs.ReplaceTrajectory(TrajectoryFromKeyPoses(robot, key_poses));
    const evaluator::OccupancyGrid map = KartoMap(scans, options_.resolution_m);
    outputs.WriteStage(robot.scans.size() - 1, map);
    outputs.WriteFinal(map);
    std::cerr << "slamsweep-slam-slam-toolbox: " << robot.scans.size() << " scans, " << passed
              << " passed the node's filter, " << processed << " processed by the Mapper, " << loop_closures.closures
              << " loop closures\n";
    mapper.reset();
    solver.reset();
  }

 private:
  /// The node raises its stack limit to 40 MB (stack_size_to_use) before anything runs; so does the driver.
  static void RaiseStackLimit() {
    constexpr rlim_t kStack = 40'000'000;
    rlimit limit{};
    if (getrlimit(RLIMIT_STACK, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur < kStack) {
      limit.rlim_cur = limit.rlim_max == RLIM_INFINITY ? kStack : std::min(kStack, limit.rlim_max);
      setrlimit(RLIMIT_STACK, &limit);
    }
  }

  SlamToolboxOptions options_;
};

std::unique_ptr<Algorithm> Configure(Parameters& parameters, const DriverArgs& /*args*/,
                                     const evaluator::RobotLog& /*robot*/) {
  return std::make_unique<SlamToolbox>(ReadSlamToolboxOptions(parameters));
}

}  // namespace
}  // namespace slamsweep::slam::slam_toolbox_driver

int main(int argc, char** argv) {
  return slamsweep::slam::DriverMain(argc, argv, "slamsweep-slam-slam-toolbox",
                                     slamsweep::slam::slam_toolbox_driver::Configure);
}
