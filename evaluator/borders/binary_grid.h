#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace slamsweep::evaluator::inline borders {

/// A cell of a BinaryGrid in the handout's coordinates: x = column, y = up.
struct GridCell {
  int x = 0;
  int y = 0;
  friend bool operator==(const GridCell&, const GridCell&) = default;
};

/// The grid the border tracer works on, in the handout's coordinate convention: X is the
/// column and Y points UP, so cell (X, Y) is OccupancyGrid row height - 1 - Y. Cells are
/// stored row by row from Y = 0 (the bottom row) upwards: index = Y * width + X.
/// Values: kFree (0), kObstacle (1) and, after tracing, kBorder (2) for traced border cells.
struct BinaryGrid {
  static constexpr std::uint8_t kFree = 0;
  static constexpr std::uint8_t kObstacle = 1;
  static constexpr std::uint8_t kBorder = 2;

  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> cells;

  BinaryGrid() = default;
  /// A width x height grid of kFree cells; throws InputError when a size is negative.
  BinaryGrid(int width_cells, int height_cells);

  bool Contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  std::size_t Index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + x; }
  /// Unchecked access; callers guarantee Contains(x, y).
  std::uint8_t at(int x, int y) const { return cells[Index(x, y)]; }
  std::uint8_t& at(int x, int y) { return cells[Index(x, y)]; }
  /// Number of cells holding `value`.
  std::size_t Count(std::uint8_t value) const;
};

}  // namespace slamsweep::evaluator::inline borders
