#pragma once

#include "evaluator/borders/binary_grid.h"
#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::evaluator::inline borders {

/// The thresholds the handout shows, on its 0..100 occupancy scale.
inline constexpr double kAnyOccupancyThreshold = 0.0;    ///< > 0: every cell with any evidence.
inline constexpr double kLowOccupancyThreshold = 1.0;    ///< > 1.
inline constexpr double kHighOccupancyThreshold = 75.0;  ///< > 75: confident obstacles only.

/// Step 1 of the handout: a BinaryGrid (Y up, see binary_grid.h) holding kObstacle where the
/// cell's value p * 100 exceeds `threshold` (0..100 scale) and kFree elsewhere; unknown
/// cells are kFree. The comparison is made in the grid's float precision (p > float(t / 100)),
/// so a cell read from an integer map value equal to t (p = float(t / 100)) is not above t.
/// Throws InputError when `threshold` is not a number in [0, 100], or when the grid's cell
/// count is not width * height.
BinaryGrid Threshold(const OccupancyGrid& grid, double threshold);

}  // namespace slamsweep::evaluator::inline borders
