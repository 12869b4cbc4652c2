// Stage images follow map_saver's rule as the header states it: v = round(100 p) (halves away from
// zero, std::lround); v >= 65 occupied (0), v <= 25 free (254), else unknown (205). The rule is
// applied here cell by cell, the obvious way, to every float near the thresholds and to random ones.
#include "orchestrator/adapters/stage_image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace slamsweep::orchestrator {
namespace {

int ByTheRule(float p) {
  if (evaluator::OccupancyGrid::IsUnknown(p)) return kStageUnknown;
  const long v = std::lround(100.0 * p);
  if (v >= 65) return kStageOccupied;
  if (v <= 25) return kStageFree;
  return kStageUnknown;
}

TEST(StageImageTest, EveryCellFollowsTheRoundedPercentRule) {
  std::vector<float> values = {-1.0f, 0.0f, 1.0f, 0.25f, 0.255f, 0.645f, 0.65f, 0.5f, std::nanf("")};
  // Every float within a few thousand steps of the points where the class changes.
  for (const float edge : {0.245f, 0.255f, 0.645f, 0.655f}) {
    float below = edge;
    float above = edge;
    for (int step = 0; step < 4000; ++step) {
      values.push_back(below = std::nextafter(below, 0.0f));
      values.push_back(above = std::nextafter(above, 1.0f));
    }
  }
  std::mt19937 random(1);
  std::uniform_real_distribution<float> probability(0.0f, 1.0f);
  for (int i = 0; i < 20000; ++i) values.push_back(probability(random));

  evaluator::OccupancyGrid grid(static_cast<int>(values.size()), 1, 0.05);
  grid.cells = values;
  const cv::Mat image = StageImage(grid);
  ASSERT_EQ(image.cols, grid.width);
  for (int col = 0; col < grid.width; ++col) {
    ASSERT_EQ(image.at<std::uint8_t>(0, col), ByTheRule(values[static_cast<std::size_t>(col)]))
        << "p = " << values[static_cast<std::size_t>(col)];
  }
}

}  // namespace
}  // namespace slamsweep::orchestrator
