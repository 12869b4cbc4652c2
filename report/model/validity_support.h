#pragma once

#include <string>
#include <string_view>

#include "evaluator/validity/metric_validity.h"

namespace slamsweep::report::inline model {

/// Whether a ground-truth-free metric may name a best run on one sequence, and why not.
struct ValiditySupport {
  bool supported = false;
  /// One sentence for the note under the table when not supported (empty when supported).
  std::string reason;
};

/// The validity study's word on ranking runs of `sequence` by `candidate` (a ValidityQuantity key
/// such as "corners.value"). The error it must track is the most independent one the study has:
/// Kuemmerle's relations, else the ATE, else the map-versus-reference Chamfer distance; the
/// correlation is the one within noise settings (ranks among the runs one table compares).
/// - A sequence the study covers: supported only when that correlation "tracks error".
/// - A sequence without a reference (not in `own`): the sweep's own study of its other sequences
///   (all of them pooled, or the one there is), else `named` (a study the sweep names); with
///   neither, not supported.
ValiditySupport SupportFor(std::string_view candidate, std::string_view sequence, const evaluator::ValidityStudy& own,
                           const evaluator::ValidityStudy* named, std::string_view named_source);

}  // namespace slamsweep::report::inline model
