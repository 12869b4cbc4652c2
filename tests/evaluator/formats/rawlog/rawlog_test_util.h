#pragma once

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>

#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::rawlog_testing {

/// A sequence like a CARMEN log: `beams` beams from -90 deg in 180/(beams-1) or 180/beams degree steps,
/// stamps at about 2 Hz on an absolute clock with microsecond digits, a robot that drives and turns,
/// a sensor 0.2 m ahead of the robot origin, and every 7th beam a "no return" (81.91 m, above max).
inline Sequence SyntheticSequence(std::size_t scans, std::size_t beams, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> range(0.3, 30.0);
  std::uniform_real_distribution<double> step(0.0, 0.5);
  std::uniform_real_distribution<double> turn(-0.4, 0.4);
  Sequence sequence;
  sequence.name = "synthetic";
  double x = 1.5, y = -2.0, yaw = 0.3;
  double stamp_s = 1137834225.713386;
  const double increment = std::numbers::pi / static_cast<double>(beams % 2 == 1 ? beams - 1 : beams);
  for (std::size_t i = 0; i < scans; ++i) {
    LaserScan scan;
    scan.stamp_s = stamp_s;
    scan.angle_min_rad = -std::numbers::pi / 2;
    scan.angle_increment_rad = increment;
    scan.range_max_m = 80.99;
    scan.sensor_pose_on_robot = Pose::Planar(0.2, 0.0, 0.0);
    for (std::size_t b = 0; b < beams; ++b)
      scan.ranges_m.push_back(b % 7 == 3 ? 81.91f : static_cast<float>(range(random)));
    sequence.scans.push_back(scan);
    sequence.odometry.Add(stamp_s, Pose::Planar(x, y, yaw));
    const double forward = step(random);
    x += forward * std::cos(yaw);
    y += forward * std::sin(yaw);
    yaw = std::remainder(yaw + turn(random), 2 * std::numbers::pi);
    stamp_s += 0.5 + 0.000001 * static_cast<double>(random() % 1000);
  }
  return sequence;
}

/// True when `program` is on the PATH.
inline bool HaveProgram(const std::string& program) {
  return std::system(("command -v " + program + " > /dev/null 2>&1").c_str()) == 0;
}

}  // namespace slamsweep::evaluator::rawlog_testing
