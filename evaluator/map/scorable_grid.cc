#include "evaluator/map/scorable_grid.h"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

[[noreturn]] void ThrowBadCell(const OccupancyGrid& grid, std::size_t index) {
  const std::size_t row = index / static_cast<std::size_t>(grid.width);
  const std::size_t col = index % static_cast<std::size_t>(grid.width);
  std::ostringstream message;
  message << "map cell (row " << row << ", col " << col << ") holds " << grid.cells[index]
          << "; expected an occupancy probability in [0, 1] or unknown";
  throw InputError(message.str());
}

}  // namespace

ScorableGrid ScorableGrid::Check(const OccupancyGrid& grid) {
  if (grid.width <= 0 || grid.height <= 0) {
    throw InputError("map is empty (" + std::to_string(grid.width) + " x " + std::to_string(grid.height) +
                     " cells): nothing to score");
  }
  const std::size_t expected = static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height);
  if (grid.cells.size() != expected) {
    throw InputError("map has " + std::to_string(grid.cells.size()) + " cells; expected width x height = " +
                     std::to_string(grid.width) + " x " + std::to_string(grid.height));
  }
  // One branch-free pass (it vectorises) counts the cells and sums the known probabilities for
  // the occupied proportion; only when it finds a bad cell do we look for which one, so the
  // common case costs one read of the grid. The sum runs in four interleaved double
  // accumulators so that it is not one long chain of dependent adds; unknown cells (negative)
  // add +0 through a bit mask, not a branch.
  std::int64_t in_range = 0;
  std::int64_t unknown = 0;
  double partial[4] = {0.0, 0.0, 0.0, 0.0};
  const auto count = [&](float p) {
    in_range += static_cast<int>((p >= 0.0f) & (p <= 1.0f));  // NaN fails both tests
    unknown += static_cast<int>(p < 0.0f);
    const std::uint32_t keep = 0u - static_cast<std::uint32_t>(p >= 0.0f);
    return static_cast<double>(std::bit_cast<float>(std::bit_cast<std::uint32_t>(p) & keep));
  };
  const std::size_t n = grid.cells.size();
  const float* cells = grid.cells.data();
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    for (int k = 0; k < 4; ++k) partial[k] += count(cells[i + k]);
  }
  for (; i < n; ++i) partial[0] += count(cells[i]);
  const std::int64_t known = in_range;
  if (in_range + unknown != static_cast<std::int64_t>(grid.cells.size())) {
    for (std::size_t i = 0; i < grid.cells.size(); ++i) {
      const float p = grid.cells[i];
      if (!OccupancyGrid::IsUnknown(p) && !(p >= 0.0f && p <= 1.0f)) ThrowBadCell(grid, i);
    }
  }
  if (known == 0) throw InputError("map has no known cell: nothing to score");
  return ScorableGrid(grid, known, (partial[0] + partial[1]) + (partial[2] + partial[3]));
}

}  // namespace slamsweep::evaluator
