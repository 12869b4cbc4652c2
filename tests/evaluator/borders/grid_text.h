#pragma once

#include <string>
#include <vector>

#include "evaluator/borders/binary_grid.h"
#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::evaluator::testing {

/// A BinaryGrid drawn as text, as a person reads a map: rows[0] is the TOP row (Y = height - 1),
/// '#' is an obstacle (1), '2' a border mark, anything else free.
inline BinaryGrid GridFromRows(const std::vector<std::string>& rows) {
  const int height = static_cast<int>(rows.size());
  const int width = height == 0 ? 0 : static_cast<int>(rows[0].size());
  BinaryGrid grid(width, height);
  for (int r = 0; r < height; ++r) {
    for (int x = 0; x < width; ++x) {
      const char c = rows[r][x];
      grid.at(x, height - 1 - r) = c == '#'   ? BinaryGrid::kObstacle
                                   : c == '2' ? BinaryGrid::kBorder
                                              : BinaryGrid::kFree;
    }
  }
  return grid;
}

/// An OccupancyGrid drawn as text (rows[0] = top row, OccupancyGrid row 0): '#' p = 1,
/// '.' p = 0, '?' unknown.
inline OccupancyGrid OccupancyFromRows(const std::vector<std::string>& rows, double resolution_m = 0.05,
                                       GridOrigin origin = {}) {
  OccupancyGrid grid(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()), resolution_m, origin);
  for (int row = 0; row < grid.height; ++row) {
    for (int col = 0; col < grid.width; ++col) {
      const char c = rows[row][col];
      grid.at(row, col) = c == '#' ? 1.0f : c == '?' ? OccupancyGrid::kUnknown : 0.0f;
    }
  }
  return grid;
}

}  // namespace slamsweep::evaluator::testing
