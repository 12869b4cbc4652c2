#include "evaluator/map_metrics/canvas_crop.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline map_metrics {

CellWindow KnownCellsWindow(const OccupancyGrid& grid, int margin_cells) {
  if (margin_cells < 0) {
    throw InputError("crop_margin_cells: expected 0 or more cells, got " + std::to_string(margin_cells));
  }
  if (grid.width < 0 || grid.height < 0 ||
      grid.cells.size() != static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height)) {
    throw InputError("map has " + std::to_string(grid.cells.size()) + " cells; expected width x height = " +
                     std::to_string(grid.width) + " x " + std::to_string(grid.height));
  }
  int min_col = grid.width, max_col = -1, min_row = grid.height, max_row = -1;
  for (int row = 0; row < grid.height; ++row) {
    const float* cells = grid.cells.data() + static_cast<std::size_t>(row) * grid.width;
    // The first and last known cell of the row bound it; rows without one are skipped whole.
    int first = 0;
    while (first < grid.width && OccupancyGrid::IsUnknown(cells[first])) ++first;
    if (first == grid.width) continue;
    int last = grid.width - 1;
    while (OccupancyGrid::IsUnknown(cells[last])) --last;
    min_col = std::min(min_col, first);
    max_col = std::max(max_col, last);
    min_row = std::min(min_row, row);
    max_row = row;
  }
  if (max_row < 0) return CellWindow{0, 0, grid.width, grid.height};
  const int col0 = std::max(0, min_col - margin_cells);
  const int row0 = std::max(0, min_row - margin_cells);
  const int col1 = std::min(grid.width - 1, max_col + margin_cells);
  const int row1 = std::min(grid.height - 1, max_row + margin_cells);
  return CellWindow{col0, row0, col1 - col0 + 1, row1 - row0 + 1};
}

namespace {

/// Throws unless `window` is non-empty and inside `grid`.
void CheckWindow(const OccupancyGrid& grid, const CellWindow& window) {
  if (window.width <= 0 || window.height <= 0 || window.col < 0 || window.row < 0 ||
      window.col + window.width > grid.width || window.row + window.height > grid.height) {
    throw InputError("crop window " + std::to_string(window.width) + " x " + std::to_string(window.height) + " at (" +
                     std::to_string(window.col) + ", " + std::to_string(window.row) + ") does not fit the " +
                     std::to_string(grid.width) + " x " + std::to_string(grid.height) + " map");
  }
}

/// The origin is the world pose of the lower-left corner; the window's lower-left cell lies
/// `col` cells right of and `height - row - window.height` cells above the grid's.
GridOrigin CroppedOrigin(const OccupancyGrid& grid, const CellWindow& window) {
  const double dx = window.col * grid.resolution_m;
  const double dy = (grid.height - window.row - window.height) * grid.resolution_m;
  const double c = std::cos(grid.origin.yaw_rad);
  const double s = std::sin(grid.origin.yaw_rad);
  GridOrigin origin = grid.origin;
  origin.x_m += c * dx - s * dy;
  origin.y_m += s * dx + c * dy;
  return origin;
}

/// Copies the window's rows to the start of `to`, row after row. In place (to = the grid's own
/// cells) this is safe: every row lands at or before where it is read, after the rows it follows.
void CopyWindowRows(const OccupancyGrid& grid, const CellWindow& window, float* to) {
  for (int row = 0; row < window.height; ++row) {
    const float* source = grid.cells.data() + static_cast<std::ptrdiff_t>(window.row + row) * grid.width + window.col;
    std::copy(source, source + window.width, to + static_cast<std::ptrdiff_t>(row) * window.width);
  }
}

}  // namespace

OccupancyGrid CropGrid(const OccupancyGrid& grid, const CellWindow& window) {
  CheckWindow(grid, window);
  OccupancyGrid cropped(window.width, window.height, grid.resolution_m, CroppedOrigin(grid, window));
  CopyWindowRows(grid, window, cropped.cells.data());
  return cropped;
}

OccupancyGrid CropGrid(OccupancyGrid&& grid, const CellWindow& window) {
  CheckWindow(grid, window);
  const GridOrigin origin = CroppedOrigin(grid, window);
  CopyWindowRows(grid, window, grid.cells.data());
  grid.cells.resize(static_cast<std::size_t>(window.width) * static_cast<std::size_t>(window.height));
  grid.width = window.width;
  grid.height = window.height;
  grid.origin = origin;
  return std::move(grid);
}

}  // namespace slamsweep::evaluator::inline map_metrics
