#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline sequence {

/// The median and the 95th percentile of one spacing over every pair of consecutive scans
/// (linear interpolation between order statistics: the value at rank (n - 1) * p of the sorted steps).
struct SpacingPercentiles {
  double median = 0.0;
  double p95 = 0.0;
  auto operator<=>(const SpacingPercentiles&) const = default;
};

/// How far apart consecutive scans are, in time and in the robot's motion. Travel and rotation come
/// from the odometry poses at the scans (what a SLAM program has, not the reference): the straight-line
/// distance between the two positions and the angle of the relative rotation, whatever the path between.
struct ScanSpacing {
  /// Pairs of consecutive scans measured (scans - 1).
  std::size_t steps = 0;
  SpacingPercentiles gap_s;
  SpacingPercentiles travel_m;
  SpacingPercentiles rotation_rad;
  /// False when every odometry pose is the same (a log without odometry): travel and rotation then
  /// say nothing about the scans, and no verdict on density is given.
  bool odometry_moves = false;
  auto operator<=>(const ScanSpacing&) const = default;
};

/// The spacing of `sequence`'s consecutive scans; absent with fewer than two scans. Pure: reads the
/// scan stamps and the odometry poses (one per scan, ValidateSequence's invariant).
std::optional<ScanSpacing> ComputeScanSpacing(const Sequence& sequence);

/// Scans further apart than this in median travel are too far apart for scan matching. The bound lies
/// between the intel run's every scan (where Cartographer worked) and every 5th scan (where it lost most of
/// its accuracy): docs/data-density.md. Rotation is shown, not judged: the study has no log sparse in it alone.
struct SparseScanThreshold {
  double median_travel_m = 0.0;
};
/// The threshold slamsweep marks sparse data by (scan_spacing.cc says which measurements it rests on).
SparseScanThreshold SparseScanThresholdInUse();

/// Whether consecutive scans are too far apart for scan matching: the median travel beyond
/// SparseScanThresholdInUse(). Absent when the odometry does not move.
std::optional<bool> TooSparseForScanMatching(const ScanSpacing& spacing);

/// One sentence for a user when the scans are too sparse ("" otherwise): the measured medians, the
/// threshold and where it comes from.
std::string SparseScanWarning(const ScanSpacing& spacing);

/// result.json's and `data info`'s "scan_spacing" block (orchestrator/DESIGN.md): the percentiles,
/// the verdict (null when the odometry does not move) and the threshold it applied.
nlohmann::json ScanSpacingJson(const ScanSpacing& spacing);
/// The block back (the report reads it from result.json); InputError naming the field otherwise.
ScanSpacing ScanSpacingFromJson(const nlohmann::json& block);

}  // namespace slamsweep::evaluator::inline sequence
