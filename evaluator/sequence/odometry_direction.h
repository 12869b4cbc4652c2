#pragma once

#include <cstddef>
#include <span>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/pose.h"
#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline sequence {

/// Which way two consecutive scans say the robot moved over an odometry step.
enum class StepDirection { kUndecided, kAlong, kAgainst };

/// Places the hits of `later` at `step` (the odometry's motion from `earlier` to `later`) and at the
/// step with its translation negated, and sums for each the squared distance from every placed hit to
/// the nearest hit of `earlier` (at most 10 cm). kAgainst when the negated step leaves clearly less
/// (under 0.9 times), kAlong in the opposite case, else kUndecided (a corridor, an empty view, a step
/// under 5 mm, below the logs' 1 cm range resolution once doubled).
StepDirection StepDirectionByScans(const LaserScan& earlier, const LaserScan& later, const Pose& step);

/// What RestoreReversing found and did.
struct ReversingRepair {
  /// Reading steps of 2 cm or more, and how many of them move backward as logged.
  std::size_t moving_steps = 0;
  std::size_t logged_backward_steps = 0;
  /// Scan-to-scan steps of 5 mm or more tested with StepDirectionByScans, and those reversed.
  std::size_t scan_steps_tested = 0;
  std::size_t scan_steps_reversed = 0;
  /// Whether the stream was taken for one that logs distances without their sign (and so was tested).
  bool unsigned_stream = false;
};

/// Some corrected logs (the Freiburg ones: fr079, fr101, campus) write every raw odometry step as a
/// forward move, so where the robot backs up the stream drives it forward: each reversal becomes an
/// error of twice its length. A stream of at least 100 moving steps with not one backward is taken as
/// such; for it, every scan step the scans say went against the logged motion gets its readings'
/// translations negated (turns unchanged) and the chain is recomposed. A stream that logs any backward
/// step is left as it is. `scan_readings[i]` is the reading of `scans[i]` (ascending).
ReversingRepair RestoreReversing(Trajectory& readings, std::span<const std::size_t> scan_readings,
                                 std::span<const LaserScan> scans);

}  // namespace slamsweep::evaluator::inline sequence
