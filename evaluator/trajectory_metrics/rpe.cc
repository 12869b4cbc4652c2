#include "evaluator/trajectory_metrics/rpe.h"

#include <optional>
#include <string>
#include <utility>

namespace slamsweep::evaluator::inline trajectory_metrics {

Rpe::Rpe(RpeOptions options) : options_(std::move(options)) {
  ValidateAssociationOptions(options_.association);
  ValidateAlignmentOptions(options_.alignment);
  ValidatePairSelectionOptions(Selection());
}

PairSelectionOptions Rpe::Selection() const {
  return PairSelectionOptions{options_.delta, options_.delta_unit, options_.all_pairs, kRpeDeltaTolerance};
}

nlohmann::json Rpe::Specification() const {
  nlohmann::json specification = ToJson(options_.association);
  specification["pose_relation"] = std::string(PoseRelationName(options_.pose_relation));
  specification["alignment"] = std::string(AlignmentModeName(options_.alignment.mode));
  specification["n_to_align"] = options_.alignment.n_to_align;
  specification["delta"] = options_.delta;
  specification["delta_unit"] = std::string(DeltaUnitName(options_.delta_unit));
  specification["all_pairs"] = options_.all_pairs;
  specification["delta_tolerance"] = kRpeDeltaTolerance;
  specification["pairs_from"] = options_.pairs_from_reference ? "reference" : "estimate";
  return specification;
}

MetricResult Rpe::Compute(const Trajectory& reference, const Trajectory& estimate) const {
  const AssociatedIndices pairs_by_stamp = AssociateIndices(reference, estimate, options_.association);
  MetricResult result;
  result.alignment = ComputeAlignment(reference, estimate, pairs_by_stamp, options_.alignment);
  // The paired poses, in pair order: the inputs themselves when every pose is paired in order.
  const PairedSide paired_reference(reference, pairs_by_stamp.reference_ids);
  const PairedSide paired_estimate(estimate, pairs_by_stamp.estimate_ids);
  std::optional<Trajectory> aligned_storage;
  if (result.alignment) aligned_storage = ApplyAlignment(paired_estimate.trajectory(), *result.alignment);
  const Trajectory& aligned = aligned_storage ? *aligned_storage : paired_estimate.trajectory();

  // evo takes the pairs from the (aligned) estimate unless told otherwise.
  const std::vector<IndexPair> pairs =
      SelectPairs(options_.pairs_from_reference ? paired_reference.trajectory() : aligned, Selection());
  const std::vector<Pose>& q = paired_reference.trajectory().poses();
  const std::vector<Pose>& p = aligned.poses();
  result.errors.resize(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto [i, j] = pairs[k];
    const Pose error = Relative(Relative(q[i], q[j]), Relative(p[i], p[j]));
    result.errors[k] = options_.pose_relation == PoseRelation::kTranslation
                           ? error.position.norm()
                           : RadToDeg(RotationAngleRad(error.orientation));
  }

  FinishMetricResult("rpe", options_.pose_relation, Specification(), pairs_by_stamp, result);
  return result;
}

}  // namespace slamsweep::evaluator::inline trajectory_metrics
