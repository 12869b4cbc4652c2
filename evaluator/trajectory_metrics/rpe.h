#pragma once

#include "evaluator/core/trajectory.h"
#include "evaluator/trajectory_metrics/alignment.h"
#include "evaluator/trajectory_metrics/association.h"
#include "evaluator/trajectory_metrics/metric_result.h"
#include "evaluator/trajectory_metrics/pair_selection.h"
#include "evaluator/trajectory_metrics/pose_relation.h"

namespace slamsweep::evaluator::inline trajectory_metrics {

struct RpeOptions {
  PoseRelation pose_relation = PoseRelation::kTranslation;
  double delta = 1;
  DeltaUnit delta_unit = DeltaUnit::kFrames;
  bool all_pairs = false;
  /// Choose the pairs on the reference instead of the aligned estimate (evo's
  /// --pairs_from_reference): every estimate is then scored on the same stretches of the path.
  bool pairs_from_reference = false;
  AssociationOptions association;
  AlignmentOptions alignment;
};

/// evo's default relative tolerance for all-pairs path and angle selection (--delta_tol).
inline constexpr double kRpeDeltaTolerance = 0.1;

/// Relative pose error, as evo_rpe: associate, align (optional), choose index pairs (i, j) on the
/// aligned estimate (evo's default; see SelectPairs) or on the reference, then per pair
/// E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j) with Q the reference and P the estimate, reporting |t(E)| (m)
/// or the angle of R(E) (deg). Compute is const and thread-safe.
class Rpe {
 public:
  /// Throws InputError naming the first invalid option.
  explicit Rpe(RpeOptions options);

  /// Throws InputError when no pairs associate, the alignment is degenerate or delta selects no
  /// pose pairs.
  MetricResult Compute(const Trajectory& reference, const Trajectory& estimate) const;

  const RpeOptions& options() const { return options_; }
  /// pose_relation, alignment, n_to_align, t_max_diff_s, t_offset_s, delta, delta_unit,
  /// all_pairs, delta_tolerance and pairs_from ("estimate" or "reference").
  nlohmann::json Specification() const;

 private:
  PairSelectionOptions Selection() const;

  RpeOptions options_;
};

}  // namespace slamsweep::evaluator::inline trajectory_metrics
