#include "report/images/overlay_alignment.h"

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "evaluator/trajectory_metrics/association.h"

namespace slamsweep::report::inline images {

evaluator::Alignment InverseAlignment(const evaluator::Alignment& alignment) {
  evaluator::Alignment inverse;
  inverse.planar = alignment.planar;
  inverse.scale = 1.0 / alignment.scale;
  inverse.rotation = alignment.rotation.transpose();
  // p = R S q + t  =>  q = S^-1 R^T (p - t) = R^T S^-1 p - S^-1 R^T t, as S and R commute.
  Eigen::Vector3d shift = alignment.rotation.transpose() * alignment.translation;
  shift.x() *= inverse.scale;
  shift.y() *= inverse.scale;
  if (!alignment.planar) shift.z() *= inverse.scale;
  inverse.translation = -shift;
  return inverse;
}

ReferenceInMapFrame AlignReferenceOntoEstimate(const evaluator::Trajectory& reference,
                                               const evaluator::Trajectory& estimate, const std::string& align,
                                               double t_max_diff_s) {
  const evaluator::AlignmentMode mode = evaluator::ParseAlignmentMode(align);
  if (mode == evaluator::AlignmentMode::kNone) return {reference, "reference as recorded (no alignment)"};
  try {
    const evaluator::Association pairs = evaluator::Associate(reference, estimate, {.t_max_diff_s = t_max_diff_s});
    const std::optional<evaluator::Alignment> alignment =
        evaluator::ComputeAlignment(pairs.reference, pairs.estimate, {.mode = mode});
    ReferenceInMapFrame placed;
    placed.reference = alignment ? evaluator::ApplyAlignment(reference, InverseAlignment(*alignment)) : reference;
    placed.note = fmt::format("reference aligned onto the estimate ({}, {} pairs)", align, pairs.estimate.size());
    return placed;
  } catch (const evaluator::InputError& error) {
    return {std::nullopt, fmt::format("reference not shown: cannot align ({})", error.what())};
  }
}

}  // namespace slamsweep::report::inline images
