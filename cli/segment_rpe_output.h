#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "evaluator/core/trajectory.h"
#include "evaluator/trajectory_metrics/association.h"

namespace slamsweep::cli {

/// `--segments` of `slamsweep eval rpe`: "auto" (10-50 % of the reference path, rounded to 1 m) or
/// a comma-separated list of lengths in metres ("5,10,20"). Throws InputError naming the option
/// for anything else. nullopt = auto.
std::optional<std::vector<double>> ParseSegmentsOption(const std::string& text);

/// `slamsweep eval rpe REF EST --segments ...`: the segment RPE (evaluator SegmentRpe) at every
/// length, as one JSON object (`json`) or a table with one line per length.
void PrintSegmentRpe(const evaluator::Trajectory& reference, const evaluator::Trajectory& estimate,
                     const std::optional<std::vector<double>>& lengths_m,
                     const evaluator::AssociationOptions& association, bool json, std::ostream& out);

}  // namespace slamsweep::cli
