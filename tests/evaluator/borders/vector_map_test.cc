#include "evaluator/borders/vector_map.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "evaluator/borders/border_tracing.h"
#include "evaluator/borders/polygon_simplify.h"
#include "evaluator/borders/threshold.h"
#include "evaluator/core/input_error.h"
#include "tests/evaluator/borders/grid_text.h"

namespace slamsweep::evaluator {
namespace {

using ::slamsweep::evaluator::testing::OccupancyFromRows;

// 5 x 5 cells of 0.5 m with the lower-left corner at (10, -2): cell (X, Y) has its centre at
// (10 + (X + 0.5) * 0.5, -2 + (Y + 0.5) * 0.5), Y counted up from the bottom row.
OccupancyGrid SquareMap() {
  return OccupancyFromRows(
      {
          ".....",
          ".###.",
          ".###.",
          ".###.",
          ".....",
      },
      0.5, GridOrigin{10.0, -2.0, 0.0});
}

TEST(VectorMapTest, SolidSquareBecomesFourCornerPolygon) {
  const VectorMap map = Vectorize(SquareMap(), VectorizeOptions{});
  ASSERT_EQ(map.polygons.size(), 1u);
  const Polygon& polygon = map.polygons[0];
  EXPECT_EQ(polygon.kind, BorderKind::kOuter);
  EXPECT_EQ(polygon.traced_cell_count, 8u);
  // Corners of the traced ring (1,3) (1,1) (3,1) (3,3), in traced (counter-clockwise) order.
  ASSERT_EQ(polygon.vertices.size(), 4u);
  EXPECT_DOUBLE_EQ(polygon.vertices[0].x_m, 10.75);
  EXPECT_DOUBLE_EQ(polygon.vertices[0].y_m, -0.25);
  EXPECT_DOUBLE_EQ(polygon.vertices[1].x_m, 10.75);
  EXPECT_DOUBLE_EQ(polygon.vertices[1].y_m, -1.25);
  EXPECT_DOUBLE_EQ(polygon.vertices[2].x_m, 11.75);
  EXPECT_DOUBLE_EQ(polygon.vertices[2].y_m, -1.25);
  EXPECT_DOUBLE_EQ(polygon.vertices[3].x_m, 11.75);
  EXPECT_DOUBLE_EQ(polygon.vertices[3].y_m, -0.25);
  // 8 straight steps of one cell (0.5 m).
  EXPECT_DOUBLE_EQ(polygon.border_length_m, 4.0);
  EXPECT_EQ(map.obstacle_count, 1u);
  EXPECT_EQ(map.hole_count, 0u);
  EXPECT_DOUBLE_EQ(map.border_length_m, 4.0);
  EXPECT_EQ(map.vertex_count, 4u);
}

TEST(VectorMapTest, StorageNumbersFollowTheHandout) {
  const VectorMap map = Vectorize(SquareMap(), VectorizeOptions{});
  EXPECT_EQ(map.raster_bytes, 25u * 4u);           // 25 float cells
  EXPECT_EQ(map.vector_bytes, 4u * 2u * 4u + 4u);  // 4 vertices * 2 floats + 1 count
}

TEST(VectorMapTest, SquareWithHoleCountsOneObstacleAndOneHole) {
  const VectorMap map = Vectorize(OccupancyFromRows(
                                      {
                                          ".........",
                                          ".#######.",
                                          ".#######.",
                                          ".##...##.",
                                          ".##...##.",
                                          ".##...##.",
                                          ".#######.",
                                          ".#######.",
                                          ".........",
                                      },
                                      0.1),
                                  VectorizeOptions{75.0, 0.0});
  ASSERT_EQ(map.polygons.size(), 2u);
  EXPECT_EQ(map.obstacle_count, 1u);
  EXPECT_EQ(map.hole_count, 1u);
  EXPECT_EQ(map.polygons[1].kind, BorderKind::kHole);
  // Outer ring: 24 straight steps; hole ring (cells 4-adjacent to the 3 x 3 hole): 8 straight
  // and 4 diagonal steps.
  EXPECT_NEAR(map.border_length_m, 0.1 * (24.0 + 8.0 + 4.0 * std::numbers::sqrt2), 1e-12);
  // Tolerance 0: the outer square keeps its 4 corners; the hole ring is an octagon.
  EXPECT_EQ(map.polygons[0].vertices.size(), 4u);
  EXPECT_EQ(map.polygons[1].vertices.size(), 8u);
  EXPECT_EQ(map.vector_bytes, 12u * 8u + 2u * 4u);
}

TEST(VectorMapTest, ThresholdSelectsWhichCellsAreObstacles) {
  // Two separate blocks: one with p = 0.5 (50 on the handout scale), one with p = 1.
  OccupancyGrid grid = OccupancyFromRows({
      "........",
      ".##..##.",
      ".##..##.",
      "........",
  });
  grid.at(1, 1) = grid.at(1, 2) = grid.at(2, 1) = grid.at(2, 2) = 0.5f;
  EXPECT_EQ(Vectorize(grid, {0.0, 1.0}).obstacle_count, 2u);
  EXPECT_EQ(Vectorize(grid, {1.0, 1.0}).obstacle_count, 2u);
  EXPECT_EQ(Vectorize(grid, {50.0, 1.0}).obstacle_count, 1u);
  EXPECT_EQ(Vectorize(grid, {75.0, 1.0}).obstacle_count, 1u);
  EXPECT_EQ(Vectorize(grid, {100.0, 1.0}).obstacle_count, 0u);
}

TEST(VectorMapTest, IsolatedCellsAreCountedButAreNotObstacles) {
  const VectorMap map = Vectorize(OccupancyFromRows({
                                      ".....",
                                      ".#...",
                                      "...#.",
                                      ".....",
                                  }),
                                  VectorizeOptions{});
  EXPECT_EQ(map.obstacle_count, 0u);
  EXPECT_EQ(map.isolated_cell_count, 2u);
  EXPECT_EQ(map.vector_bytes, 0u);
}

TEST(VectorMapTest, OneCellWideWallCountsBothFaces) {
  const VectorMap map = Vectorize(OccupancyFromRows(
                                      {
                                          "......",
                                          ".####.",
                                          "......",
                                      },
                                      1.0),
                                  VectorizeOptions{});
  ASSERT_EQ(map.polygons.size(), 1u);
  EXPECT_EQ(map.obstacle_count, 1u);
  EXPECT_DOUBLE_EQ(map.border_length_m, 6.0);  // 3 m east and 3 m back
  EXPECT_EQ(map.polygons[0].vertices.size(), 2u);
}

TEST(VectorMapTest, StatsJsonCarriesOptionsAndNumbers) {
  const nlohmann::json stats = Vectorize(SquareMap(), VectorizeOptions{60.0, 0.5}).StatsJson();
  EXPECT_EQ(stats.at("options").at("threshold"), 60.0);
  EXPECT_EQ(stats.at("options").at("simplify_tolerance_cells"), 0.5);
  EXPECT_EQ(stats.at("obstacle_count"), 1);
  EXPECT_EQ(stats.at("vertex_count"), 4);
  EXPECT_EQ(stats.at("raster_bytes"), 100);
  EXPECT_EQ(stats.at("vector_bytes"), 36);
  EXPECT_DOUBLE_EQ(stats.at("border_length_m").get<double>(), 4.0);
}

TEST(VectorMapTest, BadOptionsAndGridsAreInputErrors) {
  const OccupancyGrid grid = SquareMap();
  EXPECT_THROW(Vectorize(grid, {-1.0, 1.0}), InputError);
  EXPECT_THROW(Vectorize(grid, {75.0, -1.0}), InputError);
  EXPECT_THROW(Vectorize(grid, {75.0, std::numeric_limits<double>::infinity()}), InputError);
  OccupancyGrid no_resolution = grid;
  no_resolution.resolution_m = 0.0;
  EXPECT_THROW(Vectorize(no_resolution, {}), InputError);
  OccupancyGrid short_cells = grid;
  short_cells.cells.resize(3);
  EXPECT_THROW(Vectorize(short_cells, {}), InputError);
  try {
    Vectorize(grid, {75.0, -2.0});
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("simplify_tolerance_cells"));
  }
}

TEST(VectorMapTest, OptionsJsonRoundTripAndRejectsUnknownKeys) {
  const VectorizeOptions options{10.0, 2.5};
  const nlohmann::json json = options;
  const auto back = json.get<VectorizeOptions>();
  EXPECT_EQ(back.threshold, 10.0);
  EXPECT_EQ(back.simplify_tolerance_cells, 2.5);
  EXPECT_EQ(nlohmann::json::object().get<VectorizeOptions>().threshold, 75.0);
  EXPECT_THROW((nlohmann::json{{"treshold", 10}}.get<VectorizeOptions>()), InputError);
  EXPECT_THROW((nlohmann::json{{"threshold", "high"}}.get<VectorizeOptions>()), InputError);
  EXPECT_THROW((nlohmann::json{{"threshold", 300}}.get<VectorizeOptions>()), InputError);
  EXPECT_THROW((nlohmann::json::array().get<VectorizeOptions>()), InputError);
}

// Vectorize leaves cells inside straight runs out before simplifying (a speed-up it argues
// cannot change the result). Check that claim against the plain pipeline built from the public
// steps: every traced border simplified whole with SimplifyClosedRing.
TEST(VectorMapTest, PolygonsEqualPlainSimplificationOfEveryTracedBorder) {
  std::mt19937 random(99);
  for (int trial = 0; trial < 200; ++trial) {
    const int width = 2 + static_cast<int>(random() % 30);
    const int height = 2 + static_cast<int>(random() % 30);
    OccupancyGrid grid(width, height, 0.1, GridOrigin{-3.0, 7.0, 0.0}, 0.0f);
    // Blocks and lines rather than noise, so that borders have long straight runs.
    for (int k = 0; k < 6; ++k) {
      const int row0 = static_cast<int>(random() % height);
      const int col0 = static_cast<int>(random() % width);
      const int rows = 1 + static_cast<int>(random() % 8);
      const int cols = 1 + static_cast<int>(random() % 8);
      const bool carve = k >= 4;
      for (int r = row0; r < std::min(height, row0 + rows); ++r) {
        for (int c = col0; c < std::min(width, col0 + cols); ++c) grid.at(r, c) = carve ? 0.0f : 1.0f;
      }
    }
    for (int k = 0; k < width * height / 20; ++k) {
      grid.at(static_cast<int>(random() % height), static_cast<int>(random() % width)) = 1.0f;
    }
    const double tolerance = std::vector<double>{0.0, 0.5, 1.0, 2.5}[trial % 4];
    SCOPED_TRACE(::testing::Message() << "trial " << trial << ", tolerance " << tolerance);

    const VectorMap map = Vectorize(grid, VectorizeOptions{50.0, tolerance});
    const BorderTracing tracing = TraceBorders(Threshold(grid, 50.0));
    ASSERT_EQ(map.polygons.size(), tracing.borders.size());
    for (std::size_t b = 0; b < tracing.borders.size(); ++b) {
      const std::vector<GridCell>& cells = tracing.borders[b].cells;
      std::vector<PlanarPoint> ring;
      for (const GridCell& cell : cells) ring.push_back({static_cast<double>(cell.x), static_cast<double>(cell.y)});
      std::vector<PointM> expected;
      for (const std::size_t i : SimplifyClosedRing(ring, tolerance)) {
        expected.push_back({-3.0 + (cells[i].x + 0.5) * 0.1, 7.0 + (cells[i].y + 0.5) * 0.1});
      }
      const std::vector<PointM>& actual = map.polygons[b].vertices;
      ASSERT_EQ(actual.size(), expected.size()) << "border " << b;
      for (std::size_t v = 0; v < expected.size(); ++v) {
        EXPECT_NEAR(actual[v].x_m, expected[v].x_m, 1e-12);
        EXPECT_NEAR(actual[v].y_m, expected[v].y_m, 1e-12);
      }
    }
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
