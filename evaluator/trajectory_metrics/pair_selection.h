#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline trajectory_metrics {

/// The unit of the RPE step `delta`: poses (frames), metres travelled, seconds elapsed, or
/// degrees turned.
enum class DeltaUnit { kFrames, kMeters, kSeconds, kDegrees };

/// "f", "m", "s" or "d" (evo's --delta_unit letters); anything else is an InputError that lists
/// the valid values.
DeltaUnit ParseDeltaUnit(std::string_view name);
std::string_view DeltaUnitName(DeltaUnit unit);

/// Pose indices (first < second) whose relative motion the RPE compares.
struct IndexPair {
  std::size_t first = 0;
  std::size_t second = 0;
};

struct PairSelectionOptions {
  double delta = 1.0;
  DeltaUnit unit = DeltaUnit::kFrames;
  /// false: consecutive, non-overlapping steps; true: every start pose.
  bool all_pairs = false;
  /// All-pairs tolerance for metres, seconds and degrees, relative to delta (evo's --delta_tol).
  double relative_tolerance = 0.1;
};

/// Throws InputError naming the option when delta is negative or not finite, not a positive
/// integer for frames, or above 180 for degrees, or when the tolerance is negative.
void ValidatePairSelectionOptions(const PairSelectionOptions& options);

/// The pairs evo's filters choose (metrics.id_pairs_from_delta with rel_delta_tol):
/// - frames (filter_pairs_by_index): consecutive (0, d), (d, 2d), ...; all pairs (i, i + d).
/// - metres (filter_pairs_by_path): consecutive: walking from pose 0, the path length since the
///   last selected pose (starting at 0) is accumulated; a pose where it reaches delta is selected
///   and the sum restarts; neighbouring selected poses form the pairs, so the first pair starts at
///   the first selected pose, not at pose 0. All pairs: for each i, the j > i whose path length
///   from i is nearest delta (lowest j on a tie), kept when within delta * tolerance.
/// - degrees (filter_pairs_by_angle): consecutive: the rotation angles between neighbouring poses
///   are summed from pose 0; when the sum reaches delta the pair (start, current) is taken and the
///   next pair starts there. All pairs: every (i, j > i) whose direct rotation angle lies within
///   delta +- delta * tolerance (O(n^2), as in evo).
/// - seconds (not in evo): the metres rule applied to elapsed time, i.e. with |t_k - t_(k-1)| in
///   place of the distance between neighbouring poses.
/// The all-pairs path and time searches use binary search on the accumulated sums (O(n log n))
/// and give evo's argmin result. Throws InputError when no pair is found, naming delta and unit.
std::vector<IndexPair> SelectPairs(const Trajectory& trajectory, const PairSelectionOptions& options);

/// SelectPairs without the "no pair" error: empty when delta selects nothing (a segment length
/// longer than the path). Still throws InputError for invalid options.
std::vector<IndexPair> FindPairs(const Trajectory& trajectory, const PairSelectionOptions& options);

}  // namespace slamsweep::evaluator::inline trajectory_metrics
