#include "evaluator/borders/binary_grid.h"

#include <algorithm>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline borders {

BinaryGrid::BinaryGrid(int width_cells, int height_cells) : width(width_cells), height(height_cells) {
  if (width_cells < 0 || height_cells < 0) {
    throw InputError("binary grid size must not be negative, got " + std::to_string(width_cells) + " x " +
                     std::to_string(height_cells));
  }
  cells.assign(static_cast<std::size_t>(width_cells) * static_cast<std::size_t>(height_cells), kFree);
}

std::size_t BinaryGrid::Count(std::uint8_t value) const {
  return static_cast<std::size_t>(std::count(cells.begin(), cells.end(), value));
}

}  // namespace slamsweep::evaluator::inline borders
