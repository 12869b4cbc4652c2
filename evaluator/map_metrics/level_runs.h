#pragma once

#include <cstdint>
#include <vector>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/map_metrics/otsu.h"

namespace slamsweep::evaluator::inline map_metrics {

/// The map's 8-bit image, value = round(255 * (1 - p)) (free 255, occupied 0), with unknown
/// cells kept apart, stored as runs of equal value row by row. A map is mostly long stretches
/// of one value, so thresholding runs is far cheaper than thresholding cells.
struct LevelRuns {
  static constexpr std::uint16_t kUnknownLevel = 256;

  int width = 0;
  int height = 0;
  /// Runs of row r are [row_offsets[r], row_offsets[r + 1]); they cover the row left to right.
  std::vector<std::int32_t> row_offsets;
  std::vector<std::int32_t> begin_col;
  /// Image value 0..255, or kUnknownLevel.
  std::vector<std::uint16_t> level;
  Histogram256 known_histogram{};
  std::int64_t unknown_cells = 0;

  int end_col(int run, int row) const { return run + 1 < row_offsets[row + 1] ? begin_col[run + 1] : width; }
};

/// The 8-bit value of a known cell: round(255 * (1 - p)), halves rounded up.
inline int ImageValue(float p) { return static_cast<int>(255.0 * (1.0 - static_cast<double>(p)) + 0.5); }

/// Builds the runs of a grid whose known cells hold probabilities in [0, 1] (ScorableGrid).
LevelRuns BuildLevelRuns(const OccupancyGrid& grid);

}  // namespace slamsweep::evaluator::inline map_metrics
