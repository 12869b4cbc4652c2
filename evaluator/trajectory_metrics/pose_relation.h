#pragma once

#include <string_view>

namespace slamsweep::evaluator::inline trajectory_metrics {

/// Which part of a pose error a metric reports: the translation (metres) or the angle of
/// the rotation (degrees). These are evo's `trans_part` and `angle_deg` pose relations.
enum class PoseRelation { kTranslation, kRotationDeg };

/// "trans" or "rot-deg" (the command-line spelling); anything else is an InputError that
/// lists the valid values.
PoseRelation ParsePoseRelation(std::string_view name);
/// The spelling ParsePoseRelation accepts, so specifications round-trip.
std::string_view PoseRelationName(PoseRelation relation);
/// "m" or "deg": the unit of the errors under this relation.
std::string_view PoseRelationUnit(PoseRelation relation);

}  // namespace slamsweep::evaluator::inline trajectory_metrics
