#include "evaluator/map_metrics/free_region_sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

namespace slamsweep::evaluator {
namespace {

// Enclosed regions of one binarisation, by brute force with OpenCV's labelling.
std::int64_t BruteForce(const cv::Mat& levels, int threshold, bool unknown_free, std::int64_t min_cells) {
  cv::Mat free_cells(levels.size(), CV_8UC1);
  for (int r = 0; r < levels.rows; ++r) {
    for (int c = 0; c < levels.cols; ++c) {
      const int level = levels.at<int>(r, c);
      free_cells.at<uchar>(r, c) = (level == LevelRuns::kUnknownLevel ? unknown_free : level > threshold) ? 255 : 0;
    }
  }
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(free_cells, labels, stats, centroids, 8, CV_32S);
  std::int64_t enclosed = 0;
  for (int i = 1; i < n; ++i) {
    const int x = stats.at<int>(i, cv::CC_STAT_LEFT), y = stats.at<int>(i, cv::CC_STAT_TOP);
    const bool touches = x == 0 || y == 0 || x + stats.at<int>(i, cv::CC_STAT_WIDTH) == levels.cols ||
                         y + stats.at<int>(i, cv::CC_STAT_HEIGHT) == levels.rows;
    enclosed += (!touches && stats.at<int>(i, cv::CC_STAT_AREA) >= min_cells) ? 1 : 0;
  }
  return enclosed;
}

LevelRuns RunsOf(const cv::Mat& levels) {
  LevelRuns runs;
  runs.width = levels.cols;
  runs.height = levels.rows;
  runs.row_offsets.push_back(0);
  for (int r = 0; r < levels.rows; ++r) {
    for (int c = 0; c < levels.cols; ++c) {
      const int level = levels.at<int>(r, c);
      if (c == 0 || level != levels.at<int>(r, c - 1)) {
        runs.begin_col.push_back(c);
        runs.level.push_back(static_cast<std::uint16_t>(level));
      }
      if (level == LevelRuns::kUnknownLevel) {
        ++runs.unknown_cells;
      } else {
        ++runs.known_histogram[level];
      }
    }
    runs.row_offsets.push_back(static_cast<std::int32_t>(runs.begin_col.size()));
  }
  return runs;
}

TEST(FreeRegionSweepTest, MatchesLabellingEachBinarisationSeparately) {
  cv::RNG rng(424242);
  for (int trial = 0; trial < 150; ++trial) {
    const int rows = rng.uniform(1, 30);
    const int cols = rng.uniform(1, 30);
    // A few grey levels plus unknown, in blobs and speckle so that regions nest and merge.
    const int palette[] = {0, 40, 90, 150, 200, 254, LevelRuns::kUnknownLevel};
    cv::Mat levels(rows, cols, CV_32SC1);
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < cols; ++c) {
        const bool copy_left = c > 0 && rng.uniform(0, 3) == 0;
        levels.at<int>(r, c) = copy_left ? levels.at<int>(r, c - 1) : palette[rng.uniform(0, 7)];
      }
    }
    std::vector<int> thresholds;
    for (int t = 0; t < 255; ++t) {
      if (rng.uniform(0, 40) == 0) thresholds.push_back(t);
    }
    if (thresholds.empty()) thresholds.push_back(rng.uniform(0, 255));
    const std::int64_t min_cells = rng.uniform(1, 6);
    const FreeRegionSweep sweep(RunsOf(levels), thresholds);
    for (const bool unknown_free : {false, true}) {
      const std::vector<std::int64_t> counts = sweep.Count(unknown_free, min_cells);
      ASSERT_EQ(counts.size(), thresholds.size());
      for (std::size_t k = 0; k < thresholds.size(); ++k) {
        EXPECT_EQ(counts[k], BruteForce(levels, thresholds[k], unknown_free, min_cells))
            << "trial " << trial << ", threshold " << thresholds[k] << ", unknown free " << unknown_free;
      }
    }
  }
}

TEST(FreeRegionSweepTest, NestedRoomsAreCountedAtEveryLevel) {
  // A bright room (254) inside a grey ring (150) inside a dark wall (0), on an unknown field:
  //   t < 150: the ring and the room are one region (and touch nothing);
  //   150 <= t < 254: only the room is free.
  cv::Mat levels(9, 9, CV_32SC1, cv::Scalar(LevelRuns::kUnknownLevel));
  levels(cv::Rect(1, 1, 7, 7)).setTo(0);
  levels(cv::Rect(2, 2, 5, 5)).setTo(150);
  levels(cv::Rect(3, 3, 3, 3)).setTo(254);
  levels.at<int>(4, 4) = 0;  // a pillar in the room: the room is still one region of 8 cells
  const FreeRegionSweep sweep(RunsOf(levels), {100, 200, 254});
  EXPECT_EQ(sweep.Count(false, 4), (std::vector<std::int64_t>{1, 1, 0}));
  EXPECT_EQ(sweep.Count(false, 9), (std::vector<std::int64_t>{1, 0, 0}));
  // Unknown free: the field touches the border but is not connected to the inside.
  EXPECT_EQ(sweep.Count(true, 4), (std::vector<std::int64_t>{1, 1, 0}));
}

}  // namespace
}  // namespace slamsweep::evaluator
