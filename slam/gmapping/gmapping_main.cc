// slamsweep-slam-gmapping: GMapping's Rao-Blackwellized particle filter (openslam_gmapping's
// GridSlamProcessor) on a slamsweep program input. Unlike gfs_nogui it uses each scan's real
// geometry (beam angles, max range, the laser's pose on the robot) and runs on one thread.
#include <cmath>
#include <cstdlib>
#include <memory>
#include <ostream>
#include <streambuf>
#include <vector>

#include <gmapping/gridfastslam/gridslamprocessor.h>
#include <gmapping/sensor/sensor_odometry/odometrysensor.h>
#include <gmapping/sensor/sensor_range/rangereading.h>
#include <gmapping/sensor/sensor_range/rangesensor.h>

#include "evaluator/core/input_error.h"
#include "slam/common/driver_main.h"
#include "slam/gmapping/gmapping_map.h"
#include "slam/gmapping/gmapping_options.h"
#include "slam/gmapping/gmapping_trajectory.h"

namespace slamsweep::slam::gmapping {
namespace {

/// GridSlamProcessor reports every filter step on its info stream; the run's log needs none of it.
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
};

GMapping::OrientedPoint Oriented(const evaluator::Pose& pose) {
  return GMapping::OrientedPoint(pose.position.x(), pose.position.y(), pose.Yaw());
}

/// GMapping's scan matcher has one beam table: every scan must share the first one's geometry.
void RequireOneScanGeometry(const evaluator::RobotLog& robot) {
  const evaluator::LaserScan& first = robot.scans.front();
  for (std::size_t i = 1; i < robot.scans.size(); ++i) {
    const evaluator::LaserScan& scan = robot.scans[i];
    if (scan.BeamCount() != first.BeamCount() || std::abs(scan.angle_min_rad - first.angle_min_rad) > 1e-9 ||
        std::abs(scan.angle_increment_rad - first.angle_increment_rad) > 1e-9) {
      throw evaluator::InputError("scan " + std::to_string(i) +
                                  " has another beam geometry than scan 0; GMapping needs one laser fan per log");
    }
  }
}

class Gmapping : public Algorithm {
 public:
  Gmapping(GmappingOptions options, std::uint64_t seed) : options_(options), seed_(seed) {}

  void Run(const evaluator::RobotLog& robot, DriverOutputs& outputs) override {
    // GMapping draws every sample from drand48 (utils/stat.cpp) and resamples with rand(): seeding
    // both makes a run repeatable. The fold keeps the high half of a 64-bit seed.
    const auto folded = static_cast<unsigned int>(seed_ ^ (seed_ >> 32));
    srand48(folded);
    std::srand(folded);

    const evaluator::LaserScan& first = robot.scans.front();
    const GMapping::OrientedPoint laser_pose = Oriented(first.sensor_pose_on_robot);
    auto* laser = new GMapping::RangeSensor("FLASER", static_cast<unsigned int>(first.BeamCount()),
                                            std::abs(first.angle_increment_rad), laser_pose, 0.0, options_.maxRange);
    std::vector<double> angles(first.BeamCount());
    for (std::size_t b = 0; b < angles.size(); ++b) {
      angles[b] = first.BeamAngleRad(b);
      laser->beams()[b].pose.theta = angles[b];  // the real fan, not a symmetric one
    }
    laser->updateBeamsLookup();
    auto* odometry_sensor = new GMapping::OdometrySensor("ODOM");
    // The SensorMap does not own its sensors; they live as long as the processor's readings.
    sensors_.reset(laser);
    odometry_sensor_.reset(odometry_sensor);
    GMapping::SensorMap sensor_map;
    sensor_map.insert({laser->getName(), laser});

    NullBuffer null_buffer;
    std::ostream quiet(&null_buffer);
    GMapping::GridSlamProcessor processor(quiet);
    processor.setSensorMap(sensor_map);
    const GmappingOptions& o = options_;
    processor.setMatchingParameters(o.maxUrange, o.maxRange, o.sigma, o.kernelSize, o.lstep, o.astep, o.iterations,
                                    o.lsigma, o.ogain, static_cast<unsigned int>(o.lskip));
    processor.setMotionModelParameters(o.srr, o.srt, o.str, o.stt);
    processor.setUpdateDistances(o.linearUpdate, o.angularUpdate, o.resampleThreshold);
    processor.setUpdatePeriod(o.temporalUpdate);
    processor.setgenerateMap(false);
    processor.setminimumScore(o.minimumScore);
    processor.setllsamplerange(o.llsamplerange);
    processor.setllsamplestep(o.llsamplestep);
    processor.setlasamplerange(o.lasamplerange);
    processor.setlasamplestep(o.lasamplestep);
    processor.init(static_cast<unsigned int>(o.particles), o.xmin, o.ymin, o.xmax, o.ymax, o.delta,
                   Oriented(robot.odometry.poses().front()));

    std::vector<double> ranges(first.BeamCount());
    for (std::size_t i = 0; i < robot.scans.size(); ++i) {
      const evaluator::LaserScan& scan = robot.scans[i];
      for (std::size_t b = 0; b < ranges.size(); ++b) {
        // A no-return is reported at the sensor's max range, which GMapping takes as free space only.
        ranges[b] = scan.IsHit(scan.ranges_m[b]) ? scan.ranges_m[b] : scan.range_max_m;
      }
      GMapping::RangeReading reading(static_cast<unsigned int>(ranges.size()), ranges.data(), laser, scan.stamp_s);
      reading.setPose(Oriented(robot.odometry.poses()[i]));
      processor.processScan(reading);
      const GMapping::OrientedPoint best = processor.getParticles()[processor.getBestParticleIndex()].pose;
      outputs.AddPose(i, scan.stamp_s, evaluator::Pose::Planar(best.x, best.y, best.theta));
      if (outputs.StageDue(i) && i + 1 < robot.scans.size()) {
        outputs.WriteStage(i, BestParticleMap(processor, o, angles, laser_pose));
      }
    }
    outputs.ReplaceTrajectory(BestTrajectory(processor, robot));
    const evaluator::OccupancyGrid map = BestParticleMap(processor, o, angles, laser_pose);
    outputs.WriteStage(robot.scans.size() - 1, map);
    outputs.WriteFinal(map);
  }

 private:
  GmappingOptions options_;
  std::uint64_t seed_;
  std::unique_ptr<GMapping::RangeSensor> sensors_;
  std::unique_ptr<GMapping::OdometrySensor> odometry_sensor_;
};

std::unique_ptr<Algorithm> Configure(Parameters& parameters, const DriverArgs& args, const evaluator::RobotLog& robot) {
  RequireOneScanGeometry(robot);
  return std::make_unique<Gmapping>(ReadGmappingOptions(parameters, robot.scans.front()), args.seed.value_or(0));
}

}  // namespace
}  // namespace slamsweep::slam::gmapping

int main(int argc, char** argv) {
  return slamsweep::slam::DriverMain(argc, argv, "slamsweep-slam-gmapping", slamsweep::slam::gmapping::Configure);
}
