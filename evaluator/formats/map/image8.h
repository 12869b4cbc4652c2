#pragma once

#include <opencv2/core/mat.hpp>
#include <optional>

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::evaluator::inline formats::inline map {

/// Throws InputError unless the grid has width x height > 0 cells, each unknown or holding p in [0, 1].
void RequireValidGrid(const OccupancyGrid& grid);

/// The 8-bit image of a grid (spec/metrics.md "Occupancy grid conventions"): CV_8UC1 with the
/// grid's rows (row 0 = top), free = 255, occupied = 0, value = round(255 * (1 - p)); unknown
/// cells get `unknown_value`. A known cell may land on `unknown_value` too: callers that need
/// the distinction keep the grid, or choose a value no known cell can take.
/// Throws InputError when `unknown_value` is outside 0..255, or a cell is neither unknown nor in [0, 1].
cv::Mat ToImage8(const OccupancyGrid& grid, int unknown_value);

/// The inverse of ToImage8: p = (255 - v) / 255, and cells equal to `unknown_value` are unknown.
/// Without an unknown value every cell is known: unknown space is never guessed from a grey level.
/// Throws InputError unless `image8` is a non-empty CV_8UC1, `unknown_value` is in 0..255 and
/// `resolution_m` is a positive finite number.
OccupancyGrid FromImage8(const cv::Mat& image8, std::optional<int> unknown_value, double resolution_m,
                         GridOrigin origin = {});

}  // namespace slamsweep::evaluator::inline formats::inline map
