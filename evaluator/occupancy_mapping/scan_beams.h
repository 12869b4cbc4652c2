#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/pose.h"

namespace slamsweep::evaluator::inline occupancy_mapping {

/// Throws InputError naming the scan's index unless its angles are finite, range_min_m is
/// finite and >= 0 and range_max_m > range_min_m (range_max_m may be infinite).
void ValidateScanGeometry(const LaserScan& scan, std::size_t scan_index);

/// World position and heading of the sensor: robot pose composed with the sensor's mounting.
struct SensorPose2d {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_rad = 0.0;
};
SensorPose2d SensorInWorld(const Pose& robot_pose, const LaserScan& scan);

/// What a mapper does with one beam: trace length_m from the sensor, then mark the last cell
/// occupied when marks_hit. A length of 0 means the beam is unusable (NaN, below range_min_m,
/// or a no-return that must not clear).
struct BeamUse {
  double length_m = 0.0;
  bool marks_hit = false;
};

/// Returns beyond max_range_m are cut to it and mark nothing; no-returns clear up to
/// min(no_return_range_m, range_max_m) (not at all when no_return_range_m is 0).
inline BeamUse UseBeam(const LaserScan& scan, float range_m, double max_range_m, double no_return_range_m) {
  if (!(range_m >= scan.range_min_m)) return {};  // also rejects NaN
  if (range_m < scan.range_max_m) {
    if (range_m <= max_range_m) return {range_m, true};
    return {max_range_m, false};
  }
  return {std::fmin(no_return_range_m, scan.range_max_m), false};
}

/// Cosine and sine of every beam angle in the sensor frame, recomputed only when the scan
/// geometry changes (it never does within one log), so that a beam costs no trigonometry.
class BeamDirections {
 public:
  void Update(const LaserScan& scan);
  const std::vector<double>& cos() const { return cos_; }
  const std::vector<double>& sin() const { return sin_; }

 private:
  double angle_min_rad_ = std::nan("");
  double angle_increment_rad_ = std::nan("");
  std::vector<double> cos_;
  std::vector<double> sin_;
};

}  // namespace slamsweep::evaluator::inline occupancy_mapping
