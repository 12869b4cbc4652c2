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
  const AssociatedIndices pairs = AssociateIndices(reference, estimate, options_.association);
  MetricResult result;
  result.alignment = ComputeAlignment(reference, estimate, pairs, options_.alignment);

  // Each pair's error straight from the input poses: the aligned estimate is never stored.
  const std::vector<Pose>& reference_poses = reference.poses();
  const std::vector<Pose>& estimate_poses = estimate.poses();
  const bool translation = options_.pose_relation == PoseRelation::kTranslation;
  const Alignment identity;
  const Alignment& alignment = result.alignment ? *result.alignment : identity;
  const Eigen::Quaterniond rotation(alignment.rotation);
  result.errors.resize(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const Pose& expected = reference_poses[pairs.reference_ids[k]];
    const Pose& recorded = estimate_poses[pairs.estimate_ids[k]];
    if (translation) {
      const Eigen::Vector3d actual = result.alignment ? alignment.Apply(recorded.position) : recorded.position;
      result.errors[k] = (expected.position - actual).norm();
    } else {
      const Eigen::Quaterniond actual =
          result.alignment ? (rotation * recorded.orientation).normalized() : recorded.orientation;
      result.errors[k] = RadToDeg(RotationAngleRad(expected.orientation.conjugate() * actual));
    }
  }

  FinishMetricResult("ape", options_.pose_relation, Specification(), pairs, result);
  return result;
}

}  // namespace slamsweep::evaluator::inline trajectory_metrics
