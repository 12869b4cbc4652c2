#pragma once

#include "evaluator/core/trajectory.h"
#include "evaluator/trajectory_metrics/alignment.h"
#include "evaluator/trajectory_metrics/association.h"
#include "evaluator/trajectory_metrics/metric_result.h"
#include "evaluator/trajectory_metrics/pose_relation.h"

namespace slamsweep::evaluator::inline trajectory_metrics {

struct ApeOptions {
  PoseRelation pose_relation = PoseRelation::kTranslation;
  AssociationOptions association;
  AlignmentOptions alignment;
};

/// Absolute pose error, as evo_ape: associate by timestamp, align the estimate (optional), then
/// per pair the translation error |t_ref - t_est| (m) or the rotation error, the angle of
/// R_ref^T R_est (deg). Options are fixed at construction; Compute is const and thread-safe.
class Ape {
 public:
  /// Throws InputError naming the first invalid option.
  explicit Ape(ApeOptions options);

  /// Throws InputError when no pairs associate or the alignment is degenerate. Pairs are taken by index:
  /// no pose of either trajectory is copied.
  MetricResult Compute(const Trajectory& reference, const Trajectory& estimate) const;

  const ApeOptions& options() const { return options_; }
  /// The specification stored in every result: pose_relation, alignment, n_to_align,
  /// t_max_diff_s, t_offset_s.
  nlohmann::json Specification() const;

 private:
  ApeOptions options_;
};

}  // namespace slamsweep::evaluator::inline trajectory_metrics
