// slamsweep-slam-hector: Hector SLAM (hector_slam_lib's HectorSlamProcessor) on a slamsweep program
// input: Gauss-Newton scan matching against a multi-resolution log-odds map. Deterministic.
#include <cmath>
#include <memory>

#include "slam/common/driver_main.h"
#include "slam/hector/hector_map.h"
#include "slam/hector/hector_options.h"

namespace slamsweep::slam::hector {
namespace {

Eigen::Vector3f Planar(const evaluator::Pose& pose) {
  return Eigen::Vector3f(static_cast<float>(pose.position.x()), static_cast<float>(pose.position.y()),
                         static_cast<float>(pose.Yaw()));
}

/// a^-1 * b and a * d for planar poses (x, y, yaw).
Eigen::Vector3f Between(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  const float c = std::cos(a.z()), s = std::sin(a.z());
  const float dx = b.x() - a.x(), dy = b.y() - a.y();
  return {c * dx + s * dy, -s * dx + c * dy, std::remainder(b.z() - a.z(), 2.0f * static_cast<float>(M_PI))};
}
Eigen::Vector3f Compose(const Eigen::Vector3f& a, const Eigen::Vector3f& d) {
  const float c = std::cos(a.z()), s = std::sin(a.z());
  return {a.x() + c * d.x() - s * d.y(), a.y() + s * d.x() + c * d.y(), a.z() + d.z()};
}

/// The scan's hits between laser_min_dist and laser_max_dist as points in the robot frame, in map
/// cells of the finest level (what HectorSlamProcessor::update expects), with the laser as origin.
void FillScanPoints(const evaluator::LaserScan& scan, const HectorOptions& o, hectorslam::DataContainer& points) {
  points.clear();
  const float scale = static_cast<float>(1.0 / o.map_resolution);
  const evaluator::Pose& mount = scan.sensor_pose_on_robot;
  const double mount_yaw = mount.Yaw();
  points.setOrigo(Eigen::Vector2f(static_cast<float>(mount.position.x()), static_cast<float>(mount.position.y())) *
                  scale);
  for (std::size_t b = 0; b < scan.BeamCount(); ++b) {
    const float range = scan.ranges_m[b];
    if (!scan.IsHit(range) || range < o.laser_min_dist || range > o.laser_max_dist) continue;
    const double angle = mount_yaw + scan.BeamAngleRad(b);
    const double x = mount.position.x() + range * std::cos(angle);
    const double y = mount.position.y() + range * std::sin(angle);
    points.add(Eigen::Vector2f(static_cast<float>(x), static_cast<float>(y)) * scale);
  }
}

class Hector : public Algorithm {
 public:
  explicit Hector(HectorOptions options) : options_(std::move(options)) {}

  void Run(const evaluator::RobotLog& robot, DriverOutputs& outputs) override {
    const HectorOptions& o = options_;
    hectorslam::HectorSlamProcessor processor(
        static_cast<float>(o.map_resolution), o.map_size, o.map_size,
        Eigen::Vector2f(static_cast<float>(o.map_start_x), static_cast<float>(o.map_start_y)), o.map_multi_res_levels);
    processor.setUpdateFactorFree(static_cast<float>(o.update_factor_free));
    processor.setUpdateFactorOccupied(static_cast<float>(o.update_factor_occupied));
    processor.setMapUpdateMinDistDiff(static_cast<float>(o.map_update_distance_thresh));
    processor.setMapUpdateMinAngleDiff(static_cast<float>(o.map_update_angle_thresh));

    // Trajectory and map stay in Hector's frame, which starts at the first scan's pose: both share
    // it, and the trajectory metrics align frames themselves.
    hectorslam::DataContainer points;
    Eigen::Vector3f estimate = Eigen::Vector3f::Zero();
    for (std::size_t i = 0; i < robot.scans.size(); ++i) {
      const Eigen::Vector3f odometry = Planar(robot.odometry.poses()[i]);
      Eigen::Vector3f hint = estimate;
      if (i > 0 && o.pose_hint == "odometry") {
        hint = Compose(estimate, Between(Planar(robot.odometry.poses()[i - 1]), odometry));
      }
      FillScanPoints(robot.scans[i], o, points);
      // The first scan only builds the map: there is nothing to match it against.
      processor.update(points, hint, i == 0);
      estimate = processor.getLastScanMatchPose();
      outputs.AddPose(i, robot.scans[i].stamp_s, evaluator::Pose::Planar(estimate.x(), estimate.y(), estimate.z()));
      if (outputs.StageDue(i) && i + 1 < robot.scans.size()) outputs.WriteStage(i, FinestMap(processor));
    }
    const evaluator::OccupancyGrid map = FinestMap(processor);
    outputs.WriteStage(robot.scans.size() - 1, map);
    outputs.WriteFinal(map);
  }

 private:
  HectorOptions options_;
};

std::unique_ptr<Algorithm> Configure(Parameters& parameters, const DriverArgs& /*args*/,
                                     const evaluator::RobotLog& /*robot*/) {
  return std::make_unique<Hector>(ReadHectorOptions(parameters));
}

}  // namespace
}  // namespace slamsweep::slam::hector

int main(int argc, char** argv) {
  return slamsweep::slam::DriverMain(argc, argv, "slamsweep-slam-hector", slamsweep::slam::hector::Configure);
}
