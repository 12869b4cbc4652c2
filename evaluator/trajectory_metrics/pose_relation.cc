#include "evaluator/trajectory_metrics/pose_relation.h"

#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline trajectory_metrics {

PoseRelation ParsePoseRelation(std::string_view name) {
  if (name == "trans") return PoseRelation::kTranslation;
  if (name == "rot-deg") return PoseRelation::kRotationDeg;
  throw InputError("pose relation: expected one of trans, rot-deg; got '" + std::string(name) + "'");
}

std::string_view PoseRelationName(PoseRelation relation) {
  return relation == PoseRelation::kTranslation ? "trans" : "rot-deg";
}

std::string_view PoseRelationUnit(PoseRelation relation) {
  return relation == PoseRelation::kTranslation ? "m" : "deg";
}

}  // namespace slamsweep::evaluator::inline trajectory_metrics
