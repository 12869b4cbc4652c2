#include "evaluator/trajectory_metrics/ape.h"

#include <string>
#include <utility>

namespace slamsweep::evaluator::inline trajectory_metrics {

Ape::Ape(ApeOptions options) : options_(std::move(options)) {
  ValidateAssociationOptions(options_.association);
  ValidateAlignmentOptions(options_.alignment);
}

nlohmann::json Ape::Specification() const {
  nlohmann::json specification = ToJson(options_.association);
  specification["pose_relation"] = std::string(PoseRelationName(options_.pose_relation));
  specification["alignment"] = std::string(AlignmentModeName(options_.alignment.mode));
  specification["n_to_align"] = options_.alignment.n_to_align;
  return specification;
}

MetricResult Ape::Compute(const Trajectory& reference, const Trajectory& estimate) const {
  return Score(Associate(reference, estimate, options_.association));
}

MetricResult Ape::Compute(Trajectory&& reference, Trajectory&& estimate) const {
  return Score(Associate(std::move(reference), std::move(estimate), options_.association));
}

MetricResult Ape::Score(Association association) const {
  MetricResult result;
  result.alignment = ComputeAlignment(association.reference, association.estimate, options_.alignment);
  const Trajectory aligned = result.alignment ? ApplyAlignment(std::move(association.estimate), *result.alignment)
                                              : std::move(association.estimate);

  const std::vector<Pose>& reference_poses = association.reference.poses();
  const std::vector<Pose>& estimate_poses = aligned.poses();
  result.errors.resize(reference_poses.size());
  for (std::size_t i = 0; i < reference_poses.size(); ++i) {
    const Pose& expected = reference_poses[i];
    const Pose& actual = estimate_poses[i];
    result.errors[i] = options_.pose_relation == PoseRelation::kTranslation
                           ? (expected.position - actual.position).norm()
                           : RadToDeg(RotationAngleRad(expected.orientation.conjugate() * actual.orientation));
  }

  FinishMetricResult("ape", options_.pose_relation, Specification(), association, result);
  return result;
}

}  // namespace slamsweep::evaluator::inline trajectory_metrics
