#include "evaluator/borders/threshold.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

// One row of cells with the occupancy values of a ROS map (0..100 scale) as read into p.
OccupancyGrid RowOfValues(const std::vector<float>& p) {
  OccupancyGrid grid(static_cast<int>(p.size()), 1, 0.05);
  grid.cells = p;
  return grid;
}

std::vector<int> Row0(const BinaryGrid& grid) {
  std::vector<int> values;
  for (int x = 0; x < grid.width; ++x) values.push_back(grid.at(x, 0));
  return values;
}

// Values on the 0..100 scale: unknown, 0, 0.5, 1, 2, 75, 76, 100 (p = value / 100 in float).
const std::vector<float> kValues = {OccupancyGrid::kUnknown, 0.0f, 0.005f, 0.01f, 0.02f, 0.75f, 0.76f, 1.0f};

TEST(ThresholdTest, AboveZeroSelectsEveryCellWithEvidence) {
  EXPECT_THAT(Row0(Threshold(RowOfValues(kValues), kAnyOccupancyThreshold)),
              ::testing::ElementsAre(0, 0, 1, 1, 1, 1, 1, 1));
}

TEST(ThresholdTest, AboveOneExcludesValueOneItself) {
  EXPECT_THAT(Row0(Threshold(RowOfValues(kValues), kLowOccupancyThreshold)),
              ::testing::ElementsAre(0, 0, 0, 0, 1, 1, 1, 1));
}

TEST(ThresholdTest, AboveSeventyFiveKeepsConfidentObstaclesOnly) {
  EXPECT_THAT(Row0(Threshold(RowOfValues(kValues), kHighOccupancyThreshold)),
              ::testing::ElementsAre(0, 0, 0, 0, 0, 0, 1, 1));
}

TEST(ThresholdTest, UnknownIsFreeEvenAtThresholdZero) {
  OccupancyGrid grid(3, 3, 0.1);  // all unknown
  EXPECT_EQ(Threshold(grid, 0.0).Count(BinaryGrid::kFree), 9u);
}

TEST(ThresholdTest, RowsAreFlippedSoThatYPointsUp) {
  OccupancyGrid grid(3, 2, 0.1, {}, 0.0f);
  grid.at(0, 2) = 1.0f;  // top row, right column
  grid.at(1, 0) = 1.0f;  // bottom row, left column
  const BinaryGrid binary = Threshold(grid, 75.0);
  EXPECT_EQ(binary.width, 3);
  EXPECT_EQ(binary.height, 2);
  EXPECT_EQ(binary.at(2, 1), 1);
  EXPECT_EQ(binary.at(0, 0), 1);
  EXPECT_EQ(binary.Count(1), 2u);
}

TEST(ThresholdTest, ThresholdOutOfRangeIsAnInputError) {
  const OccupancyGrid grid = RowOfValues(kValues);
  EXPECT_THROW(Threshold(grid, -0.5), InputError);
  EXPECT_THROW(Threshold(grid, 100.5), InputError);
  EXPECT_THROW(Threshold(grid, std::numeric_limits<double>::quiet_NaN()), InputError);
  try {
    Threshold(grid, 250.0);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("threshold"));
    EXPECT_THAT(error.what(), ::testing::HasSubstr("[0, 100]"));
  }
}

TEST(ThresholdTest, CellCountMismatchIsAnInputError) {
  OccupancyGrid grid(4, 4, 0.05);
  grid.cells.pop_back();
  EXPECT_THROW(Threshold(grid, 50.0), InputError);
}

}  // namespace
}  // namespace slamsweep::evaluator
