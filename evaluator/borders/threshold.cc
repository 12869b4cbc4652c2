#include "evaluator/borders/threshold.h"

#include <cmath>
#include <cstddef>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {

BinaryGrid Threshold(const OccupancyGrid& grid, double threshold) {
  if (!std::isfinite(threshold) || threshold < 0.0 || threshold > 100.0) {
    throw InputError(fmt::format("option threshold: expected a number in [0, 100] (occupancy scale), got {}",
                                 threshold));
  }
  if (grid.width < 0 || grid.height < 0 ||
      grid.cells.size() != static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height)) {
    throw InputError(fmt::format("occupancy grid: {} cells do not fill its {} x {} size", grid.cells.size(),
                                 grid.width, grid.height));
  }
  // Unknown cells (p = -1) and NaN both fail `p > limit`, so they become free without a branch.
  const float limit = static_cast<float>(threshold / 100.0);
  BinaryGrid binary(grid.width, grid.height);
  for (int row = 0; row < grid.height; ++row) {
    const float* source = grid.cells.data() + static_cast<std::size_t>(row) * grid.width;
    std::uint8_t* target = binary.cells.data() + binary.Index(0, grid.height - 1 - row);
    for (int col = 0; col < grid.width; ++col) target[col] = source[col] > limit ? 1 : 0;
  }
  return binary;
}

}  // namespace slamsweep::evaluator
