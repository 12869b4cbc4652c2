#pragma once

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::evaluator::inline map_metrics {

/// A rectangle of a grid in cells, in the grid's image order (row 0 = top row).
struct CellWindow {
  int col = 0;
  int row = 0;
  int width = 0;
  int height = 0;
  bool operator==(const CellWindow&) const = default;
};

/// The canvas rule of spec/metrics.md: the bounding box of the known cells, grown by
/// `margin_cells` on each side and clamped to the grid. A grid without a known cell keeps its
/// whole window (there is nothing to crop to). Throws InputError for a negative margin or a grid
/// whose cell count is not width x height.
CellWindow KnownCellsWindow(const OccupancyGrid& grid, int margin_cells);

/// The cells of `window` as a grid of their own, with the origin moved so that every kept cell
/// stays where it was in the world (origin yaw included). Throws InputError when the window is
/// empty or leaves the grid.
OccupancyGrid CropGrid(const OccupancyGrid& grid, const CellWindow& window);
/// CropGrid of a grid that is no longer needed: the kept cells move up in place, without new memory.
OccupancyGrid CropGrid(OccupancyGrid&& grid, const CellWindow& window);

}  // namespace slamsweep::evaluator::inline map_metrics
