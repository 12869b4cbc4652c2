#include "evaluator/core/occupancy_grid.h"

#include <string>

#include "evaluator/core/huge_pages.h"
#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline core {

OccupancyGrid::OccupancyGrid(int width_cells, int height_cells, double resolution, GridOrigin grid_origin, float fill)
    : width(width_cells), height(height_cells), resolution_m(resolution), origin(grid_origin) {
  if (width_cells <= 0 || height_cells <= 0) {
    throw InputError("grid size must be positive, got " + std::to_string(width_cells) + " x " +
                     std::to_string(height_cells));
  }
  if (!(resolution > 0.0)) throw InputError("grid resolution must be > 0 m/cell, got " + std::to_string(resolution));
  const std::size_t count = static_cast<std::size_t>(width_cells) * static_cast<std::size_t>(height_cells);
  cells.reserve(count);
  AdviseHugePages(cells);  // a 2000 x 2000 grid: a few huge-page faults instead of 4,000 small ones
  cells.assign(count, fill);
}

}  // namespace slamsweep::evaluator::inline core
