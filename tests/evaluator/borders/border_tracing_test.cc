#include "evaluator/borders/border_tracing.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "evaluator/core/input_error.h"
#include "tests/evaluator/borders/grid_text.h"

namespace slamsweep::evaluator {

// Readable failure messages for cell lists.
void PrintTo(const GridCell& cell, std::ostream* out) { *out << "(" << cell.x << ", " << cell.y << ")"; }

namespace {

using ::slamsweep::evaluator::testing::GridFromRows;
using ::testing::ElementsAre;
using ::testing::ElementsAreArray;

GridCell C(int x, int y) { return {x, y}; }

TEST(BorderTracingTest, IsolatedCellIsErased) {
  const BorderTracing result = TraceBorders(GridFromRows({
      ".....",
      ".....",
      "..#..",
      ".....",
      ".....",
  }));
  EXPECT_TRUE(result.borders.empty());
  EXPECT_EQ(result.erased_cell_count, 1u);
  EXPECT_EQ(result.marked.Count(BinaryGrid::kFree), 25u);
}

TEST(BorderTracingTest, TraceWholeBorderReturnsNulloptForIsolatedCell) {
  BinaryGrid grid = GridFromRows({"...", ".#.", "..."});
  EXPECT_EQ(TraceWholeBorder(grid, C(1, 1)), std::nullopt);
  EXPECT_EQ(grid.at(1, 1), BinaryGrid::kFree);
}

TEST(BorderTracingTest, HorizontalLineIsWalkedThereAndBack) {
  // Start (1,1); d' = 5 finds nothing below, E (d = 0) is taken; at the east end the search
  // from d' = 7 only finds W (d = 4), and the walk west ends on the start cell.
  const BorderTracing result = TraceBorders(GridFromRows({
      "......",
      ".####.",
      "......",
  }));
  ASSERT_EQ(result.borders.size(), 1u);
  EXPECT_THAT(result.borders[0].cells, ElementsAre(C(1, 1), C(2, 1), C(3, 1), C(4, 1), C(3, 1), C(2, 1)));
  EXPECT_EQ(result.marked.Count(BinaryGrid::kBorder), 4u);
  EXPECT_EQ(TwiceSignedAreaCells2(result.borders[0]), 0);
}

TEST(BorderTracingTest, SolidSquareBorderIsItsOuterRingCounterClockwise) {
  // Start = top-left cell (1,3), the first 1 of the scan. d = 7 -> d' = 5 (SW, empty), then
  // S is found: the first move is south (d = 6), down the left side, east along the bottom,
  // north up the right side and west along the top back to the start.
  const BorderTracing result = TraceBorders(GridFromRows({
      ".....",
      ".###.",
      ".###.",
      ".###.",
      ".....",
  }));
  ASSERT_EQ(result.borders.size(), 1u);
  EXPECT_THAT(result.borders[0].cells,
              ElementsAre(C(1, 3), C(1, 2), C(1, 1), C(2, 1), C(3, 1), C(3, 2), C(3, 3), C(2, 3)));
  // The centre is not on the border and keeps its 1.
  EXPECT_EQ(result.marked.at(2, 2), BinaryGrid::kObstacle);
  EXPECT_EQ(result.marked.Count(BinaryGrid::kBorder), 8u);
  EXPECT_GT(TwiceSignedAreaCells2(result.borders[0]), 0);
  EXPECT_EQ(TwiceSignedAreaCells2(result.borders[0]), 2 * 4);  // centres span a 2 x 2 square
}

TEST(BorderTracingTest, SquareWithHoleGivesOuterThenInnerBorder) {
  const BorderTracing result = TraceBorders(GridFromRows({
      ".........",  // Y = 8
      ".#######.",  // Y = 7
      ".#######.",  // Y = 6
      ".##...##.",  // Y = 5
      ".##...##.",  // Y = 4
      ".##...##.",  // Y = 3
      ".#######.",  // Y = 2
      ".#######.",  // Y = 1
      ".........",  // Y = 0
  }));
  ASSERT_EQ(result.borders.size(), 2u);
  const std::vector<GridCell>& outer = result.borders[0].cells;
  ASSERT_EQ(outer.size(), 24u);
  EXPECT_EQ(outer[0], C(1, 7));
  EXPECT_EQ(outer[1], C(1, 6));
  EXPECT_EQ(outer[6], C(1, 1));
  EXPECT_EQ(outer[7], C(2, 1));
  EXPECT_EQ(outer[12], C(7, 1));
  EXPECT_EQ(outer[18], C(7, 7));
  EXPECT_EQ(outer[23], C(2, 7));
  // The hole's border starts right of the hole's top row, (6,5), where the left neighbour is 0.
  // From d' = 5: SW (5,4) is in the hole, S (6,4) is taken; at (6,3) SW (5,2) is taken, and so on:
  // the cells 4-adjacent to the hole, clockwise (the obstacle stays on the left).
  EXPECT_THAT(result.borders[1].cells, ElementsAre(C(6, 5), C(6, 4), C(6, 3), C(5, 2), C(4, 2), C(3, 2), C(2, 3),
                                                   C(2, 4), C(2, 5), C(3, 6), C(4, 6), C(5, 6)));
  EXPECT_GT(TwiceSignedAreaCells2(result.borders[0]), 0);
  EXPECT_LT(TwiceSignedAreaCells2(result.borders[1]), 0);
  // Corner cells of the hole's frame touch the hole only diagonally and are not traced.
  EXPECT_EQ(result.marked.at(2, 2), BinaryGrid::kObstacle);
}

TEST(BorderTracingTest, OneCellHoleGivesDiamondInnerBorder) {
  const BorderTracing result = TraceBorders(GridFromRows({
      ".......",
      ".#####.",
      ".#####.",
      ".##.##.",
      ".#####.",
      ".#####.",
      ".......",
  }));
  ASSERT_EQ(result.borders.size(), 2u);
  // Start (4,3); SW (3,2) is taken (d = 5), then from d' = 3: NW (2,3); from d' = 1: NE (3,4);
  // from d' = 7: SE is the start.
  EXPECT_THAT(result.borders[1].cells, ElementsAre(C(4, 3), C(3, 2), C(2, 3), C(3, 4)));
  EXPECT_EQ(TwiceSignedAreaCells2(result.borders[1]), -4);
}

TEST(BorderTracingTest, ObjectFillingTheGridSkipsOffGridNeighbours) {
  const BorderTracing result = TraceBorders(GridFromRows({
      "###",
      "###",
      "###",
  }));
  ASSERT_EQ(result.borders.size(), 1u);
  EXPECT_THAT(result.borders[0].cells,
              ElementsAre(C(0, 2), C(0, 1), C(0, 0), C(1, 0), C(2, 0), C(2, 1), C(2, 2), C(1, 2)));
}

TEST(BorderTracingTest, VerticalLineOnTheLeftEdge) {
  const BorderTracing result = TraceBorders(GridFromRows({
      "#..",
      "#..",
      "#..",
      "#..",
  }));
  ASSERT_EQ(result.borders.size(), 1u);
  EXPECT_THAT(result.borders[0].cells, ElementsAre(C(0, 3), C(0, 2), C(0, 1), C(0, 0), C(0, 1), C(0, 2)));
}

TEST(BorderTracingTest, ShapeTouchingRightAndTopEdges) {
  // Start (1,2): SW (0,1) empty, S (1,1) taken; at (1,1) E (2,1) [after SW, S, SE empty];
  // at (2,1) the search from d' = 7 skips SE, E, NE (off grid), takes N (2,2); from d' = 1 it
  // skips NE, N and NW (off grid) and takes W = start.
  const BorderTracing result = TraceBorders(GridFromRows({
      ".##",
      ".##",
      "...",
  }));
  ASSERT_EQ(result.borders.size(), 1u);
  EXPECT_THAT(result.borders[0].cells, ElementsAre(C(1, 2), C(1, 1), C(2, 1), C(2, 2)));
}

TEST(BorderTracingTest, ObjectOnBottomRowOnlyIsNeverStarted) {
  const BorderTracing result = TraceBorders(GridFromRows({
      ".....",
      ".....",
      ".###.",
  }));
  EXPECT_TRUE(result.borders.empty());
  EXPECT_EQ(result.erased_cell_count, 0u);
  // Not traced and not erased: the cells keep their 1.
  EXPECT_EQ(result.marked.Count(BinaryGrid::kObstacle), 3u);
}

TEST(BorderTracingTest, IsolatedCellOnBottomRowIsNotErased) {
  const BorderTracing result = TraceBorders(GridFromRows({"...", "...", ".#."}));
  EXPECT_TRUE(result.borders.empty());
  EXPECT_EQ(result.marked.at(1, 0), BinaryGrid::kObstacle);
}

TEST(BorderTracingTest, SingleRowGridIsNeverScanned) {
  const BorderTracing result = TraceBorders(GridFromRows({"#.##"}));
  EXPECT_TRUE(result.borders.empty());
  EXPECT_EQ(result.marked.Count(BinaryGrid::kObstacle), 3u);
}

TEST(BorderTracingTest, ObjectReachingBottomRowIsTracedThroughIt) {
  const BorderTracing result = TraceBorders(GridFromRows({
      ".#.",
      ".##",
  }));
  ASSERT_EQ(result.borders.size(), 1u);
  // Start (1,1): SW (0,0) empty, S (1,0) taken; at (1,0) from d' = 5: SW, S, SE off grid, E (2,0)
  // taken; at (2,0) from d' = 7: SE, E off grid, NE off grid, N (2,1) empty, NW (1,1) = start.
  EXPECT_THAT(result.borders[0].cells, ElementsAre(C(1, 1), C(1, 0), C(2, 0)));
}

TEST(BorderTracingTest, TraceStopsAtFirstReturnToStartCell) {
  // A "V": the start cell joins two arms. The trace goes down the left arm and back to the
  // start, and stops there (the handout's stop rule), so the right arm starts its own border,
  // which crosses the start cell to the left arm and back.
  const BorderTracing v = TraceBorders(GridFromRows({
      "........",  // Y = 6
      ".....#..",  // Y = 5
      "....#.#.",  // Y = 4
      "........",  // Y = 3
      "........",  // Y = 2
      "........",  // Y = 1
      "........",  // Y = 0
  }));
  ASSERT_EQ(v.borders.size(), 2u);
  EXPECT_THAT(v.borders[0].cells, ElementsAre(C(5, 5), C(4, 4)));
  EXPECT_THAT(v.borders[1].cells, ElementsAre(C(6, 4), C(5, 5), C(4, 4), C(5, 5)));
}

TEST(BorderTracingTest, TraceWholeBorderRejectsBadStart) {
  BinaryGrid grid = GridFromRows({"...", ".##", "..."});
  EXPECT_THROW(TraceWholeBorder(grid, C(3, 1)), InputError);
  EXPECT_THROW(TraceWholeBorder(grid, C(-1, 0)), InputError);
  EXPECT_THROW(TraceWholeBorder(grid, C(0, 0)), InputError);  // a free cell
  try {
    TraceWholeBorder(grid, C(0, 1));
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("(0, 1)"));
  }
  ASSERT_NE(TraceWholeBorder(grid, C(1, 1)), std::nullopt);
  EXPECT_THROW(TraceWholeBorder(grid, C(1, 1)), InputError);  // already traced: holds 2
}

TEST(BorderTracingTest, InconsistentGridIsAnInputError) {
  BinaryGrid grid(3, 3);
  grid.cells.resize(5);
  EXPECT_THROW(TraceBorders(grid), InputError);
  EXPECT_THROW(BinaryGrid(-1, 2), InputError);
}

TEST(BorderTracingTest, EmptyGridHasNoBorders) {
  EXPECT_TRUE(TraceBorders(BinaryGrid(0, 0)).borders.empty());
  EXPECT_TRUE(TraceBorders(BinaryGrid(4, 0)).borders.empty());
}

// Properties any correct trace has, checked on random grids of several densities and shapes
// (edges included, so that off-grid handling is exercised; run under AddressSanitizer too).
TEST(BorderTracingTest, RandomGridsSatisfyTraceInvariants) {
  std::mt19937 random(12345);
  for (int trial = 0; trial < 300; ++trial) {
    const int width = 1 + static_cast<int>(random() % 23);
    const int height = 1 + static_cast<int>(random() % 23);
    const double density = 0.1 + 0.8 * (trial % 10) / 9.0;
    std::bernoulli_distribution occupied(density);
    BinaryGrid input(width, height);
    for (auto& cell : input.cells) cell = occupied(random) ? 1 : 0;

    const BorderTracing result = TraceBorders(input);
    const BinaryGrid& marked = result.marked;
    SCOPED_TRACE(::testing::Message() << "trial " << trial << " " << width << " x " << height);
    std::set<std::pair<int, int>> traced;
    for (const Border& border : result.borders) {
      ASSERT_GE(border.cells.size(), 2u);
      for (std::size_t i = 0; i < border.cells.size(); ++i) {
        const GridCell& a = border.cells[i];
        const GridCell& b = border.cells[(i + 1) % border.cells.size()];
        ASSERT_TRUE(marked.Contains(a.x, a.y));
        EXPECT_EQ(marked.at(a.x, a.y), BinaryGrid::kBorder);
        EXPECT_EQ(input.at(a.x, a.y), BinaryGrid::kObstacle);
        // Consecutive cells are distinct 8-neighbours, the last one a neighbour of the first.
        EXPECT_LE(std::abs(a.x - b.x), 1);
        EXPECT_LE(std::abs(a.y - b.y), 1);
        EXPECT_FALSE(a == b);
        traced.insert({a.x, a.y});
      }
    }
    EXPECT_EQ(traced.size(), marked.Count(BinaryGrid::kBorder));
    EXPECT_EQ(input.Count(1), marked.Count(1) + marked.Count(2) + result.erased_cell_count);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        if (input.at(x, y) == 0) {
          EXPECT_EQ(marked.at(x, y), 0);
        }
        // Every cell that could start a border was started: an untraced 1 above row 0 has an
        // occupied left neighbour.
        if (y >= 1 && marked.at(x, y) == BinaryGrid::kObstacle) {
          EXPECT_TRUE(x > 0 && marked.at(x - 1, y) != 0) << "untraced start cell (" << x << ", " << y << ")";
        }
      }
    }
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
