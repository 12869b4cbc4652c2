#include "evaluator/borders/border_tracing.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

// Traces from a kObstacle cell (unchecked) and appends the border to `cells`. Returns false
// and erases the start cell when it is isolated.
bool Trace(BinaryGrid& grid, const int start_x, const int start_y, std::vector<GridCell>& cells) {
  const int width = grid.width;
  const int height = grid.height;
  std::uint8_t* const data = grid.cells.data();
  std::ptrdiff_t offset[8];
  for (int d = 0; d < 8; ++d) offset[d] = kDirectionDx[d] + static_cast<std::ptrdiff_t>(kDirectionDy[d]) * width;

  // Every step enters a cell from one of 8 directions, and the walk is deterministic, so a
  // walk longer than 8 steps per cell repeats a state without meeting the start: a bug, not
  // bad input. The cap turns such a bug into an exception instead of a hang.
  const std::uint64_t max_steps = 8ull * grid.cells.size() + 8;

  int x = start_x;
  int y = start_y;
  std::size_t index = grid.Index(x, y);
  data[index] = BinaryGrid::kBorder;
  cells.push_back({x, y});
  int d = 7;
  for (std::uint64_t step = 0;; ++step) {
    if (step > max_steps) {
      throw std::logic_error(fmt::format("border trace from ({}, {}) did not return to its start", start_x, start_y));
    }
    const int first = (d & 1) != 0 ? (d + 6) & 7 : (d + 7) & 7;
    // Away from the grid edge every neighbour exists, so the bounds test is only paid there.
    const bool interior = x > 0 && y > 0 && x < width - 1 && y < height - 1;
    int found = -1;
    for (int k = 0; k < 8; ++k) {
      const int dir = (first + k) & 7;
      if (!interior && !grid.Contains(x + kDirectionDx[dir], y + kDirectionDy[dir])) continue;
      if (data[index + offset[dir]] != BinaryGrid::kFree) {
        found = dir;
        break;
      }
    }
    if (found < 0) {
      // Only the start cell can lack a neighbour: every later cell has the one it came from.
      data[index] = BinaryGrid::kFree;
      cells.pop_back();
      return false;
    }
    d = found;
    x += kDirectionDx[d];
    y += kDirectionDy[d];
    index += offset[d];
    if (x == start_x && y == start_y) return true;
    data[index] = BinaryGrid::kBorder;
    cells.push_back({x, y});
  }
}

}  // namespace

std::optional<Border> TraceWholeBorder(BinaryGrid& grid, GridCell start) {
  if (grid.cells.size() != static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height)) {
    throw InputError(fmt::format("binary grid: {} cells do not fill its {} x {} size", grid.cells.size(), grid.width,
                                 grid.height));
  }
  if (!grid.Contains(start.x, start.y)) {
    throw InputError(fmt::format("border start ({}, {}) is outside the {} x {} grid", start.x, start.y, grid.width,
                                 grid.height));
  }
  if (grid.at(start.x, start.y) != BinaryGrid::kObstacle) {
    throw InputError(fmt::format("border start ({}, {}) holds {}, expected an untraced obstacle cell (1)", start.x,
                                 start.y, grid.at(start.x, start.y)));
  }
  Border border;
  if (!Trace(grid, start.x, start.y, border.cells)) return std::nullopt;
  return border;
}

BorderTracing TraceBorders(BinaryGrid grid) {
  if (grid.cells.size() != static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height)) {
    throw InputError(fmt::format("binary grid: {} cells do not fill its {} x {} size", grid.cells.size(), grid.width,
                                 grid.height));
  }
  BorderTracing result;
  std::vector<GridCell> cells;
  for (int y = grid.height - 1; y >= 1; --y) {
    const std::uint8_t* row = grid.cells.data() + grid.Index(0, y);
    for (int x = 0; x < grid.width; ++x) {
      if (row[x] != BinaryGrid::kObstacle || (x > 0 && row[x - 1] != BinaryGrid::kFree)) continue;
      cells.clear();
      if (Trace(grid, x, y, cells)) {
        result.borders.push_back(Border{cells});
      } else {
        ++result.erased_cell_count;
      }
    }
  }
  result.marked = std::move(grid);
  return result;
}

long long TwiceSignedAreaCells2(const Border& border) {
  const std::vector<GridCell>& cells = border.cells;
  long long sum = 0;
  for (std::size_t i = 0, n = cells.size(); i < n; ++i) {
    const GridCell& a = cells[i];
    const GridCell& b = cells[(i + 1) % n];
    sum += static_cast<long long>(a.x) * b.y - static_cast<long long>(b.x) * a.y;
  }
  return sum;
}

}  // namespace slamsweep::evaluator
