#include "evaluator/borders/threshold.h"

#include <fmt/format.h>

#include <cmath>
#include <cstddef>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline borders {

BinaryGrid Threshold(const OccupancyGrid& grid, double threshold) {
  if (!std::isfinite(threshold) || threshold < 0.0 || threshold > 100.0) {
    throw InputError(
        fmt::format("option threshold: expected a number in [0, 100] (occupancy scale), got {}", threshold));
  }
  if (grid.width < 0 || grid.height < 0 ||
      grid.cells.size() != static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height)) {
    throw InputError(fmt::format("occupancy grid: {} cells do not fill its {} x {} size", grid.cells.size(), grid.width,
                                 grid.height));
  }
  // Unknown cells (p = -1) and NaN both fail `p > limit`, so they become free without a branch.
  const float limit = static_cast<float>(threshold / 100.0);
  // Sizes in locals: stores through uint8_t* may alias anything, so reading grid.width in the
  // loop condition would reload it every cell and keep the compiler from vectorising.
  const std::size_t width = static_cast<std::size_t>(grid.width);
  const int height = grid.height;
  BinaryGrid binary(grid.width, height);
  const float* const source = grid.cells.data();
  std::uint8_t* const target = binary.cells.data();
  for (int row = 0; row < height; ++row) {
    const float* in = source + static_cast<std::size_t>(row) * width;
    std::uint8_t* out = target + static_cast<std::size_t>(height - 1 - row) * width;
    for (std::size_t col = 0; col < width; ++col) out[col] = in[col] > limit ? 1 : 0;
  }
  return binary;
}

}  // namespace slamsweep::evaluator::inline borders
