// slamsweep-slam-lama-pf: LaMa's PFSlam2D (iris_lama, BSD-3-Clause) as iris_lama_ros's pf_slam2d_ros node runs
// it offline (launch/pf_slam2d_offine.launch): particles drawn from the odometry at every scan, each matched and
// mapped once the odometry accumulated d_thresh or a_thresh, resampled when the effective number falls below
// half. The trajectory is the best particle's poses at the updates (odometry between them); the map is its map.
// Randomised: its one generator is seeded from the run's seed, on one thread.
#include <map>
#include <memory>
#include <vector>

#include <lama/pf_slam2d.h>

#include "evaluator/core/input_error.h"
#include "slam/common/driver_main.h"
#include "slam/common/key_pose_trajectory.h"
#include "slam/lama_shared/lama_run.h"

namespace slamsweep::slam::lama_driver {
namespace {

/// LaMa's seed for a run's seed: its 64 bits folded into the 32 LaMa takes, and 0, which LaMa replaces by a
/// fresh random seed, replaced by a fixed one (the driver contract: a run without --seed, seed 0, repeats).
constexpr std::uint32_t kSeedForZero = 0x9E3779B9u;
std::uint32_t LamaSeed(std::uint64_t seed) {
  const auto folded = static_cast<std::uint32_t>(seed ^ (seed >> 32));
  return folded == 0 ? kSeedForZero : folded;
}

class PfSlam2D : public Algorithm {
 public:
  explicit PfSlam2D(lama::PFSlam2D::Options options, ScanOptions scan) : options_(std::move(options)), scan_(scan) {}

  void Run(const evaluator::RobotLog& robot, DriverOutputs& outputs) override {
    lama::PFSlam2D slam(options_);
    slam.setPrior(lama::Pose2D(0.0, 0.0, 0.0));  // the node's prior (initial_pos_x, _y, _a)
    std::vector<double> update_stamps;           // the scans the particles' pose histories belong to, in order
    evaluator::Pose key_pose, key_odometry;
    for (std::size_t i = 0; i < robot.scans.size(); ++i) {
      const evaluator::LaserScan& scan = robot.scans[i];
      const evaluator::Pose& odometry = robot.odometry.poses()[i];
      // The node hands every scan over: the particles move with each one, and update when enough motion gathered.
      if (slam.update(LamaCloud(scan, scan_), LamaPose(odometry), scan.stamp_s)) {
        update_stamps.push_back(scan.stamp_s);
        key_pose = ToPose(slam.getPose());
        key_odometry = odometry;
      }
      outputs.AddPose(i, scan.stamp_s, MovedByOdometry(key_pose, key_odometry, odometry));
      if (outputs.StageDue(i) && i + 1 < robot.scans.size()) outputs.WriteStage(i, LamaMap(*slam.getOccupancyMap()));
    }
    // The best particle's history: its pose at every update (the first scan's included), resampling kept it.
    const lama::PFSlam2D::Particle& best = slam.getParticles()[slam.getBestParticleIdx()];
    if (best.poses.size() != update_stamps.size()) {
      throw std::runtime_error("PFSlam2D's best particle has " + std::to_string(best.poses.size()) + " poses for " +
                               std::to_string(update_stamps.size()) + " updates");
    }
    std::map<double, evaluator::Pose> key_poses;
    for (std::size_t k = 0; k < update_stamps.size(); ++k) key_poses[update_stamps[k]] = ToPose(best.poses[k]);
    WriteLamaResult(robot, key_poses, *slam.getOccupancyMap(), outputs);
  }

 private:
  lama::PFSlam2D::Options options_;
  ScanOptions scan_;
};

/// pf_slam2d_ros's parameter names, with the offline launch file's values where it sets them (particles 30,
/// d_thresh 0.5, a_thresh 0.5, mrange 20; the node's own a_thresh is 0.25, mrange 16) and the node's defaults
/// otherwise, but for two: threads is 1 (the launch file's 4 draw from LaMa's one generator at once: not
/// repeatable), and the seed is the run's.
std::unique_ptr<Algorithm> Configure(Parameters& parameters, const DriverArgs& args,
                                     const evaluator::RobotLog& /*robot*/) {
  lama::PFSlam2D::Options options;
  ScanOptions scan;
  ReadSharedOptions(parameters, options, scan, "zstd");
  const int particles = parameters.Integer("particles", 30);
  if (particles < 1) throw evaluator::InputError("parameter particles: expected at least 1");
  options.particles = static_cast<std::uint32_t>(particles);
  options.srr = parameters.Real("srr", 0.1);
  options.str = parameters.Real("str", 0.2);
  options.stt = parameters.Real("stt", 0.1);
  options.srt = parameters.Real("srt", 0.2);
  options.meas_sigma = parameters.Real("sigma", 0.05);
  options.meas_sigma_gain = parameters.Real("lgain", 3.0);
  if (!(options.meas_sigma > 0)) throw evaluator::InputError("parameter sigma: expected > 0");
  if (!(options.meas_sigma_gain > 0)) throw evaluator::InputError("parameter lgain: expected > 0");
  options.threads = parameters.Integer("threads", 1);
  if (options.threads != 1) {
    throw evaluator::InputError(
        "parameter threads: only 1 is repeatable (LaMa's particles share one random generator across threads)");
  }
  options.seed = LamaSeed(args.seed.value_or(0));
  options.create_summary = false;  // the launch file's summary is a printed report, nothing a run scores
  return std::make_unique<PfSlam2D>(options, scan);
}

}  // namespace
}  // namespace slamsweep::slam::lama_driver

int main(int argc, char** argv) {
  return slamsweep::slam::DriverMain(argc, argv, "slamsweep-slam-lama-pf", slamsweep::slam::lama_driver::Configure);
}
