#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/core/statistics.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/trajectory_metrics/association.h"
#include "evaluator/trajectory_metrics/pair_selection.h"

namespace slamsweep::evaluator::inline trajectory_metrics {

/// Length of the path through the poses in order (sum of the distances between neighbours), m.
double PathLengthM(const Trajectory& trajectory);

/// The segment lengths of KITTI and rpg_trajectory_evaluation: 10, 20, 30, 40 and 50 % of
/// `path_length_m`, each rounded to whole metres; lengths that round to 0 m and repeats are left
/// out, so a path shorter than 1 m gets none.
std::vector<double> DefaultSegmentLengthsM(double path_length_m);

/// Throws InputError unless every length is finite and > 0 and the list has no repeats.
void ValidateSegmentLengths(const std::vector<double>& lengths_m);

struct SegmentRpeOptions {
  /// The segment lengths (m), ascending after construction.
  std::vector<double> lengths_m;
  AssociationOptions association;
  /// How far a segment's reference path may be from its nominal length, relative to it (evo's
  /// --delta_tol, default 0.1).
  double relative_tolerance = 0.1;
};

/// The errors of the segments of one length.
struct SegmentLengthResult {
  double length_m = 0.0;
  /// Index pairs into the associated trajectories; their reference stamps are `start_s`/`end_s`.
  std::vector<IndexPair> pairs;
  std::vector<double> start_s;
  std::vector<double> end_s;
  /// Per segment: |t(E)| in m, the same in % of length_m, and the angle of R(E) in deg per m of length_m.
  std::vector<double> translation_m;
  std::vector<double> translation_pct;
  std::vector<double> rotation_deg_per_m;
  /// Statistics of each vector; absent when no segment of this length fits in the trajectory.
  std::optional<ErrorStatistics> translation_m_statistics;
  std::optional<ErrorStatistics> translation_pct_statistics;
  std::optional<ErrorStatistics> rotation_deg_per_m_statistics;
};

struct SegmentRpeResult {
  /// One per length of the options, in ascending order.
  std::vector<SegmentLengthResult> lengths;
  /// lengths_m, delta_unit "m", all_pairs true, pairs_from "reference", delta_tolerance, alignment
  /// "none", t_max_diff_s, t_offset_s.
  nlohmann::json specification;
  std::size_t pairs = 0;  ///< associated poses
  std::size_t reference_unpaired = 0;
  std::size_t estimate_unpaired = 0;

  /// {"specification", "pairs", "reference_unpaired", "estimate_unpaired", "lengths": [{"length_m",
  /// "n", "translation_m": {statistics}, "translation_pct": {...}, "rotation_deg_per_m": {...}}]}; a
  /// length without segments has n 0 and null statistics. No per-segment errors.
  nlohmann::json ToJson() const;
};

/// Relative pose error over path segments of given lengths, as KITTI's odometry benchmark and
/// rpg_trajectory_evaluation report drift: the segments are chosen on the REFERENCE path, so every
/// estimate of a sequence is scored on the same stretches whatever its own errors. For each length
/// D the index pairs are evo's all-pairs metre selection on the associated reference (for each start
/// pose, the end pose whose path length from it is nearest D, kept within D * relative_tolerance),
/// and each pair's error is evo's E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j): so the result at D is exactly
/// `evo_rpe --delta D --delta_unit m --all_pairs --pairs_from_reference` (and Rpe with those
/// options). Translation error is |t(E)| (m) and 100 |t(E)| / D (% of the segment length),
/// rotation error the angle of R(E) / D (deg/m), as in KITTI. No alignment: relative errors do not
/// change under a rigid transform of the estimate. Compute is const and thread-safe.
class SegmentRpe {
 public:
  /// Throws InputError for invalid lengths, association options or tolerance.
  explicit SegmentRpe(SegmentRpeOptions options);

  /// A length no segment fits into has no statistics (not an error); throws InputError when no
  /// poses associate.
  SegmentRpeResult Compute(const Trajectory& reference, const Trajectory& estimate) const;

  const SegmentRpeOptions& options() const { return options_; }

 private:
  SegmentRpeOptions options_;
};

}  // namespace slamsweep::evaluator::inline trajectory_metrics
