#pragma once

#include <optional>
#include <string>

#include "evaluator/core/trajectory.h"
#include "evaluator/trajectory_metrics/alignment.h"

namespace slamsweep::report::inline images {

/// The transform that undoes `alignment`: InverseAlignment(a).Apply(a.Apply(p)) == p. Exact for
/// the alignments the evaluator makes, whose scale commutes with their rotation (planar ones
/// rotate about z and scale x and y; the others scale uniformly).
evaluator::Alignment InverseAlignment(const evaluator::Alignment& alignment);

/// The reference trajectory moved into the estimate's frame (the frame of the map), or why not.
struct ReferenceInMapFrame {
  std::optional<evaluator::Trajectory> reference;
  /// For the legend: how the reference was placed ("aligned onto the estimate: se2, 120 pairs")
  /// or why it is missing.
  std::string note;
};

/// Associates the two trajectories (t_max_diff_s), computes the evaluator's alignment of the
/// estimate onto the reference (`align`: none, origin, se2, se3, sim2, sim3) and applies its
/// inverse to the whole reference: the map was built in the estimate's frame, so the reference is
/// what has to move. An unknown `align` is an InputError naming it; data that cannot be aligned
/// (no pairs, degenerate path) is not an error: the result has no reference and the note says why.
ReferenceInMapFrame AlignReferenceOntoEstimate(const evaluator::Trajectory& reference,
                                               const evaluator::Trajectory& estimate, const std::string& align,
                                               double t_max_diff_s);

}  // namespace slamsweep::report::inline images
