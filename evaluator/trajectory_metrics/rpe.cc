#include "evaluator/trajectory_metrics/rpe.h"

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
  Association association = Associate(reference, estimate, options_.association);
  MetricResult result;
  result.alignment = ComputeAlignment(association.reference, association.estimate, options_.alignment);
  const Trajectory aligned = result.alignment ? ApplyAlignment(std::move(association.estimate), *result.alignment)
                                              : std::move(association.estimate);

  // evo takes the pairs from the (aligned) estimate unless told otherwise.
  const std::vector<IndexPair> pairs =
      SelectPairs(options_.pairs_from_reference ? association.reference : aligned, Selection());
  const std::vector<Pose>& q = association.reference.poses();
  const std::vector<Pose>& p = aligned.poses();
  result.errors.resize(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto [i, j] = pairs[k];
    const Pose error = Relative(Relative(q[i], q[j]), Relative(p[i], p[j]));
    result.errors[k] = options_.pose_relation == PoseRelation::kTranslation
                           ? error.position.norm()
                           : RadToDeg(RotationAngleRad(error.orientation));
  }

  FinishMetricResult("rpe", options_.pose_relation, Specification(), association, result);
  return result;
}

}  // namespace slamsweep::evaluator::inline trajectory_metrics
