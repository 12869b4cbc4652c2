#include "evaluator/sequence/sequence.h"

#include <fmt/format.h>

#include <cmath>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

[[noreturn]] void Fail(const Sequence& sequence, const std::string& message) {
  throw InputError("sequence '" + sequence.name + "': " + message);
}

void CheckScan(const Sequence& sequence, const LaserScan& scan, std::size_t index) {
  const std::string where = "scan " + std::to_string(index) + ": ";
  if (scan.ranges_m.empty()) Fail(sequence, where + "has no beams");
  if (!std::isfinite(scan.stamp_s)) Fail(sequence, where + "timestamp is not a finite number");
  if (!std::isfinite(scan.angle_min_rad) || !std::isfinite(scan.angle_increment_rad) ||
      scan.angle_increment_rad == 0.0) {
    Fail(sequence, where + "expected a finite start angle and a finite non-zero angle increment");
  }
  if (!(scan.range_min_m >= 0.0) || !(scan.range_max_m > scan.range_min_m) || !std::isfinite(scan.range_max_m)) {
    Fail(sequence, where + fmt::format("expected 0 <= range_min_m < range_max_m (finite), got {} and {}",
                                       scan.range_min_m, scan.range_max_m));
  }
  if (!scan.sensor_pose_on_robot.IsValid()) Fail(sequence, where + "sensor pose is not a valid pose");
}

}  // namespace

void ValidateSequence(const Sequence& sequence) {
  const std::size_t count = sequence.scans.size();
  for (std::size_t i = 0; i < count; ++i) {
    CheckScan(sequence, sequence.scans[i], i);
    if (i > 0 && !(sequence.scans[i].stamp_s > sequence.scans[i - 1].stamp_s)) {
      Fail(sequence, fmt::format("scan {}: stamp {} s does not come after the previous scan's {} s", i,
                                 sequence.scans[i].stamp_s, sequence.scans[i - 1].stamp_s));
    }
  }
  if (sequence.odometry.size() != count) {
    Fail(sequence, "expected one odometry pose per scan (" + std::to_string(count) + "), got " +
                       std::to_string(sequence.odometry.size()));
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (sequence.odometry.stamps_s()[i] != sequence.scans[i].stamp_s) {
      Fail(sequence, fmt::format("odometry pose {} has stamp {} s, its scan {} s", i, sequence.odometry.stamps_s()[i],
                                 sequence.scans[i].stamp_s));
    }
  }
}

}  // namespace slamsweep::evaluator
