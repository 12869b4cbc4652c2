#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "evaluator/borders/binary_grid.h"

namespace slamsweep::evaluator::inline borders {

/// Neighbour directions of the handout, counter-clockwise from east (Y up):
/// 0 = +X, 1 = +X+Y, 2 = +Y, 3 = -X+Y, 4 = -X, 5 = -X-Y, 6 = -Y, 7 = +X-Y.
inline constexpr int kDirectionDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
inline constexpr int kDirectionDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};

/// One traced border: the cells in the order the trace visited them, starting with the start
/// cell. The trace's final step back onto the start cell is not repeated, so the cells form a
/// closed ring (the last cell is an 8-neighbour of the first). A cell may occur more than once
/// (one-cell-wide parts are walked along both sides). The trace keeps the obstacle on its
/// left, so outer borders run counter-clockwise and hole borders clockwise (Y up).
struct Border {
  std::vector<GridCell> cells;
};

/// Result of step 2 for a whole grid.
struct BorderTracing {
  std::vector<Border> borders;        ///< In the order the scan started them.
  BinaryGrid marked;                  ///< The input with border cells set to 2 and isolated cells to 0.
  std::size_t erased_cell_count = 0;  ///< Isolated cells the scan erased.
};

/// The handout's TraceWholeBorder from `start`, which must be a kObstacle cell of `grid`
/// (InputError otherwise, naming the cell). Marks every visited cell kBorder. Starting with
/// d = 7, each step searches the 8 neighbours counter-clockwise from d' = (d + 7) mod 8 when d
/// is even, (d + 6) mod 8 when d is odd, moves to the first non-free one and makes its
/// direction the new d; neighbours off the grid are skipped without being read. The trace
/// stops when it steps back onto `start` -- the first time, even if the start cell joins
/// two loops of the border (the handout's rule; the rest is found by the scan later).
/// An isolated start cell (no non-free neighbour) is erased (set to kFree) and nullopt returned.
std::optional<Border> TraceWholeBorder(BinaryGrid& grid, GridCell start);

/// Step 2 of the handout on the whole grid: scans Y from height - 1 down to 1 (row Y = 0
/// never starts a border, as in the handout) and X from 0 to width - 1, and calls
/// TraceWholeBorder on every cell that is kObstacle and has X == 0 or a kFree left neighbour,
/// reading the grid as the traces have marked it so far. Linear in the cell count plus the
/// border length; never reads outside the grid.
BorderTracing TraceBorders(BinaryGrid grid);

/// Twice the signed (shoelace) area of the polygon through the cell centres of a closed
/// border, in cells^2: > 0 counter-clockwise (an outer border), < 0 clockwise (a hole), 0 for
/// borders that enclose no area (one-cell-wide objects).
long long TwiceSignedAreaCells2(const Border& border);

}  // namespace slamsweep::evaluator::inline borders
