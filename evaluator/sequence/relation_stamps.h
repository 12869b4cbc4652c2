#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "evaluator/core/relation.h"

namespace slamsweep::evaluator::inline sequence {

/// Moves each relation stamp onto the record (a scan or an odometry reading) whose logged stamp is nearest
/// to it, within tolerance_s (the first in file order among equal logged stamps), and gives it that record's
/// chosen stamp: relation stamps name records by the stamps they were logged with, so they follow a record
/// whose stamp the reader had to repair. A stamp with no record that near keeps its value; `unmatched`
/// counts them. `logged_s` and `chosen_s` are parallel (file order).
Relations MapRelationsOntoRecords(Relations relations, std::span<const double> logged_s,
                                  std::span<const double> chosen_s, double tolerance_s, std::size_t& unmatched);

/// The median gap between consecutive stamps once sorted, 0 for fewer than two.
double MedianSpacingS(std::vector<double> stamps);

}  // namespace slamsweep::evaluator::inline sequence
