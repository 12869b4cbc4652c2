#pragma once

#include <cstddef>
#include <vector>

namespace slamsweep::evaluator::inline core {

/// World pose of the lower-left corner of the grid (map_server's `origin`).
struct GridOrigin {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_rad = 0.0;
};

/// An occupancy grid: every cell is unknown or holds an occupancy probability p in [0, 1].
/// Cells are stored row-major in image order: row 0 is the TOP row (largest world y), the
/// order in which PGM/PNG map files store them, so that image operations see the map as a
/// person does. World y of row r is origin.y_m + (height - 1 - r + 0.5) * resolution_m.
struct OccupancyGrid {
  /// Marker for an unknown cell; every known cell holds p in [0, 1].
  static constexpr float kUnknown = -1.0f;

  int width = 0;
  int height = 0;
  double resolution_m = 0.05;
  GridOrigin origin;
  std::vector<float> cells;

  OccupancyGrid() = default;
  /// A width x height grid filled with `fill` (unknown by default).
  OccupancyGrid(int width_cells, int height_cells, double resolution, GridOrigin grid_origin = {},
                float fill = kUnknown);

  std::size_t CellCount() const { return cells.size(); }
  static bool IsUnknown(float p) { return p < 0.0f; }
  float at(int row, int col) const { return cells[static_cast<std::size_t>(row) * width + col]; }
  float& at(int row, int col) { return cells[static_cast<std::size_t>(row) * width + col]; }
  /// World coordinates (metres) of the centre of a cell, ignoring origin yaw (always 0 in practice).
  double CellCenterXM(int col) const { return origin.x_m + (col + 0.5) * resolution_m; }
  double CellCenterYM(int row) const { return origin.y_m + (height - 1 - row + 0.5) * resolution_m; }
};

}  // namespace slamsweep::evaluator::inline core
