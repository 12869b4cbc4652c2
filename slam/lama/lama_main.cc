// slamsweep-slam-lama: LaMa's Slam2D (iris_lama, BSD-3-Clause) as iris_lama_ros's slam2d_ros node runs it
// offline (launch/slam2d_offine.launch): a scan is matched against the dynamic distance map, and then mapped,
// once the odometry moved d_thresh or turned a_thresh since the last update. Slam2D keeps no trajectory: the
// pose is read after each update, and a scan between updates gets the last update's pose moved on by the
// odometry. Deterministic.
#include <map>
#include <memory>

#include <lama/slam2d.h>

#include "evaluator/core/input_error.h"
#include "slam/common/driver_main.h"
#include "slam/common/key_pose_trajectory.h"
#include "slam/lama_shared/lama_run.h"

namespace slamsweep::slam::lama_driver {
namespace {

class Slam2D : public Algorithm {
 public:
  Slam2D(lama::Slam2D::Options options, ScanOptions scan) : options_(std::move(options)), scan_(scan) {}

  void Run(const evaluator::RobotLog& robot, DriverOutputs& outputs) override {
    lama::Slam2D slam(options_);
    slam.setPose(lama::Pose2D(0.0, 0.0, 0.0));  // the node's prior (initial_pos_x, _y, _a)
    std::map<double, evaluator::Pose> key_poses;
    evaluator::Pose key_pose, key_odometry;
    for (std::size_t i = 0; i < robot.scans.size(); ++i) {
      const evaluator::LaserScan& scan = robot.scans[i];
      const evaluator::Pose& odometry = robot.odometry.poses()[i];
      const lama::Pose2D lama_odometry = LamaPose(odometry);
      // The node converts and hands over a scan only when Slam2D says the robot moved enough.
      if (slam.enoughMotion(lama_odometry) && slam.update(LamaCloud(scan, scan_), lama_odometry, scan.stamp_s)) {
        key_pose = ToPose(slam.getPose());
        key_odometry = odometry;
        key_poses[scan.stamp_s] = key_pose;
      }
      outputs.AddPose(i, scan.stamp_s, MovedByOdometry(key_pose, key_odometry, odometry));
      if (outputs.StageDue(i) && i + 1 < robot.scans.size()) outputs.WriteStage(i, LamaMap(*slam.getOccupancyMap()));
    }
    WriteLamaResult(robot, key_poses, *slam.getOccupancyMap(), outputs);
  }

 private:
  lama::Slam2D::Options options_;
  ScanOptions scan_;
};

/// slam2d_ros's parameter names, with the offline launch file's values where it sets them (d_thresh 0.5,
/// a_thresh 0.5, mrange 20; the node's own defaults are 0.01, 0.25 and 16) and the node's defaults otherwise.
std::unique_ptr<Algorithm> Configure(Parameters& parameters, const DriverArgs& /*args*/,
                                     const evaluator::RobotLog& /*robot*/) {
  lama::Slam2D::Options options;
  ScanOptions scan;
  ReadSharedOptions(parameters, options, scan, "lz4");
  const int max_iterations = parameters.Integer("max_iterations", 100);
  if (max_iterations < 1) throw evaluator::InputError("parameter max_iterations: expected at least 1");
  options.max_iter = static_cast<std::uint32_t>(max_iterations);
  options.transient_map = parameters.Flag("transient_map", false);
  options.create_summary = false;  // the launch file's summary is a printed report, nothing a run scores
  return std::make_unique<Slam2D>(options, scan);
}

}  // namespace
}  // namespace slamsweep::slam::lama_driver

int main(int argc, char** argv) {
  return slamsweep::slam::DriverMain(argc, argv, "slamsweep-slam-lama", slamsweep::slam::lama_driver::Configure);
}
