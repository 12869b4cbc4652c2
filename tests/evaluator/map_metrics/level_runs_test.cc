#include "evaluator/map_metrics/level_runs.h"

#include <gtest/gtest.h>

#include "tests/evaluator/map_metrics/map_test_util.h"

namespace slamsweep::evaluator {
namespace {

TEST(LevelRunsTest, RunsOfEqualImageValueWithHistogram) {
  // Row 0: 255 255 0 ? ?; row 1: 128 (p = 0.5) 128 (p = 0.499, also 128) 255 255 0.
  OccupancyGrid grid = testing::GridFromText({"..#??", "55..#"});
  grid.at(1, 1) = 0.499f;
  const LevelRuns runs = BuildLevelRuns(grid);
  ASSERT_EQ(runs.row_offsets, (std::vector<std::int32_t>{0, 3, 6}));
  EXPECT_EQ(runs.begin_col, (std::vector<std::int32_t>{0, 2, 3, 0, 2, 4}));
  EXPECT_EQ(runs.level, (std::vector<std::uint16_t>{255, 0, LevelRuns::kUnknownLevel, 128, 255, 0}));
  EXPECT_EQ(runs.end_col(2, 0), 5);
  EXPECT_EQ(runs.end_col(3, 1), 2);
  EXPECT_EQ(runs.unknown_cells, 2);
  EXPECT_EQ(runs.known_histogram[255], 4);
  EXPECT_EQ(runs.known_histogram[0], 2);
  EXPECT_EQ(runs.known_histogram[128], 2);
}

TEST(LevelRunsTest, ImageValueRoundsToNearest) {
  EXPECT_EQ(ImageValue(0.0f), 255);
  EXPECT_EQ(ImageValue(1.0f), 0);
  for (int v = 0; v < 256; ++v) EXPECT_EQ(ImageValue(static_cast<float>((255 - v) / 255.0)), v);
  EXPECT_EQ(ImageValue(0.5f), 128);  // 127.5 rounds up
}

}  // namespace
}  // namespace slamsweep::evaluator
