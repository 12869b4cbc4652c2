#include "evaluator/map_metrics/run_components.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <utility>
#include <vector>

namespace slamsweep::evaluator {
namespace {

// '#' foreground, anything else background.
RowRuns RunsFromText(const std::vector<std::string>& rows) {
  RowRuns runs(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()));
  for (const std::string& row : rows) {
    int open = -1;
    for (int c = 0; c < static_cast<int>(row.size()); ++c) {
      if (row[c] == '#' && open < 0) open = c;
      if (row[c] != '#' && open >= 0) {
        runs.Add(open, c);
        open = -1;
      }
    }
    if (open >= 0) runs.Add(open, static_cast<int>(row.size()));
    runs.EndRow();
  }
  return runs;
}

TEST(RunComponentsTest, DiagonalNeighboursAreConnected) {
  const RunComponentLabels labels = LabelRunComponents(RunsFromText({
      ".....",
      ".#...",
      "..#..",
      "...##",
      ".....",
  }));
  ASSERT_EQ(labels.components.size(), 1u);
  EXPECT_EQ(labels.components[0].cells, 4);
  EXPECT_TRUE(labels.components[0].touches_border);  // reaches the last column
}

TEST(RunComponentsTest, OneCellGapSeparates) {
  const RunComponentLabels labels = LabelRunComponents(RunsFromText({
      ".......",
      ".#.#...",
      ".#...#.",
      ".......",
  }));
  ASSERT_EQ(labels.components.size(), 3u);
  EXPECT_EQ(labels.components[0].cells, 2);
  EXPECT_EQ(labels.components[1].cells, 1);
  EXPECT_EQ(labels.components[2].cells, 1);
  for (const RunComponent& c : labels.components) EXPECT_FALSE(c.touches_border);
}

TEST(RunComponentsTest, UShapeJoinsLate) {
  // Two arms that meet only in the last row: one component.
  const RunComponentLabels labels = LabelRunComponents(RunsFromText({
      "#...#",
      "#...#",
      "#####",
  }));
  ASSERT_EQ(labels.components.size(), 1u);
  EXPECT_EQ(labels.components[0].cells, 9);
}

TEST(RunComponentsTest, EmptyImageHasNoComponents) {
  EXPECT_TRUE(LabelRunComponents(RunsFromText({"...", "..."})).components.empty());
}

TEST(RunComponentsTest, AgreesWithOpenCvOnRandomImages) {
  cv::RNG rng(20240601);
  for (int trial = 0; trial < 300; ++trial) {
    const int rows = rng.uniform(1, 40);
    const int cols = rng.uniform(1, 40);
    cv::Mat noise(rows, cols, CV_8UC1);
    rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
    const cv::Mat binary = noise < rng.uniform(40, 200);
    RowRuns runs(cols, rows);
    for (int r = 0; r < rows; ++r) {
      int open = -1;
      for (int c = 0; c < cols; ++c) {
        const bool on = binary.at<uchar>(r, c) != 0;
        if (on && open < 0) open = c;
        if (!on && open >= 0) {
          runs.Add(open, c);
          open = -1;
        }
      }
      if (open >= 0) runs.Add(open, cols);
      runs.EndRow();
    }
    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(binary, labels, stats, centroids, 8, CV_32S);
    const RunComponentLabels ours = LabelRunComponents(runs);
    ASSERT_EQ(static_cast<int>(ours.components.size()), n - 1) << "trial " << trial;
    // Label order may differ (OpenCV scans 2 x 2 blocks), so compare the sorted summaries.
    std::vector<std::pair<std::int64_t, bool>> expected;
    for (int i = 1; i < n; ++i) {
      const int x = stats.at<int>(i, cv::CC_STAT_LEFT), y = stats.at<int>(i, cv::CC_STAT_TOP);
      const bool touches = x == 0 || y == 0 || x + stats.at<int>(i, cv::CC_STAT_WIDTH) == cols ||
                           y + stats.at<int>(i, cv::CC_STAT_HEIGHT) == rows;
      expected.emplace_back(stats.at<int>(i, cv::CC_STAT_AREA), touches);
    }
    std::vector<std::pair<std::int64_t, bool>> actual;
    for (const RunComponent& c : ours.components) actual.emplace_back(c.cells, c.touches_border);
    std::sort(expected.begin(), expected.end());
    std::sort(actual.begin(), actual.end());
    EXPECT_EQ(actual, expected) << "trial " << trial;
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
