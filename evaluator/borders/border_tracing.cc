#include "evaluator/borders/border_tracing.h"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline borders {
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

// First non-free cell in [begin, end), or end. Free space is most of a map, so it is skipped
// eight cells at a time.
std::uint8_t* FindNonFree(std::uint8_t* begin, std::uint8_t* const end) {
  while (end - begin >= 8) {
    std::uint64_t word;
    std::memcpy(&word, begin, sizeof(word));
    if (word != 0) break;
    begin += 8;
  }
  while (begin != end && *begin == BinaryGrid::kFree) ++begin;
  return begin;
}

// First free cell in [begin, end), or end.
std::uint8_t* FindFree(std::uint8_t* begin, std::uint8_t* const end) {
  void* found = std::memchr(begin, BinaryGrid::kFree, static_cast<std::size_t>(end - begin));
  return found == nullptr ? end : static_cast<std::uint8_t*>(found);
}

}  // namespace

std::optional<Border> TraceWholeBorder(BinaryGrid& grid, GridCell start) {
  if (grid.cells.size() != static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height)) {
    throw InputError(
        fmt::format("binary grid: {} cells do not fill its {} x {} size", grid.cells.size(), grid.width, grid.height));
  }
  if (!grid.Contains(start.x, start.y)) {
    throw InputError(
        fmt::format("border start ({}, {}) is outside the {} x {} grid", start.x, start.y, grid.width, grid.height));
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
    throw InputError(
        fmt::format("binary grid: {} cells do not fill its {} x {} size", grid.cells.size(), grid.width, grid.height));
  }
  BorderTracing result;
  std::vector<GridCell> cells;
  // Only the first cell of each run of non-free cells has a free (or no) left neighbour, so the
  // scan jumps from run to run instead of testing every cell. This equals the cell-by-cell scan
  // of the handout because a trace never changes which cells of the scanned row are free,
  // except that it may erase its own isolated start cell, whose right neighbour is free anyway.
  for (int y = grid.height - 1; y >= 1; --y) {
    std::uint8_t* const row = grid.cells.data() + grid.Index(0, y);
    std::uint8_t* const end = row + grid.width;
    for (std::uint8_t* run = FindNonFree(row, end); run != end; run = FindNonFree(FindFree(run, end), end)) {
      if (*run != BinaryGrid::kObstacle) continue;  // already traced (2): not a start
      cells.clear();
      if (Trace(grid, static_cast<int>(run - row), y, cells)) {
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
  if (cells.empty()) return 0;
  long long sum = 0;
  const GridCell* a = &cells.back();  // the closing edge first, so no modulo in the loop
  for (const GridCell& b : cells) {
    sum += static_cast<long long>(a->x) * b.y - static_cast<long long>(b.x) * a->y;
    a = &b;
  }
  return sum;
}

}  // namespace slamsweep::evaluator::inline borders
