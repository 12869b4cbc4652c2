#include "evaluator/map_metrics/harris_corners.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "evaluator/map_metrics/zero_scan.h"
#include "tests/evaluator/map_metrics/map_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

std::vector<CornerCell> Direct(const cv::Mat& image, const HarrisSelectionOptions& o) {
  std::vector<cv::Point2f> points;
  cv::goodFeaturesToTrack(image, points, 0, o.quality_level, o.min_distance_cells, cv::noArray(), o.block_size_cells,
                          o.aperture_cells, true, o.harris_k);
  std::vector<CornerCell> cells;
  for (const cv::Point2f& p : points) cells.push_back({static_cast<int>(p.y), static_cast<int>(p.x)});
  return cells;
}

void ExpectSameCorners(const std::vector<CornerCell>& actual, const std::vector<CornerCell>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    ASSERT_EQ(actual[i].row, expected[i].row) << "corner " << i;
    ASSERT_EQ(actual[i].col, expected[i].col) << "corner " << i;
  }
}

// The cleaned structure image of the corner count, built here with plain OpenCV calls (not
// with the code under test): 1 - p / 0, Gaussian 5x5 sigma 1, Laplacian 3x3, |LoG| > 10 % of
// its maximum, blobs under 5 cells dropped.
cv::Mat CleanedLog(const OccupancyGrid& grid) {
  cv::Mat remapped(grid.height, grid.width, CV_32FC1);
  for (int r = 0; r < grid.height; ++r) {
    for (int c = 0; c < grid.width; ++c) {
      const float p = grid.at(r, c);
      remapped.at<float>(r, c) = OccupancyGrid::IsUnknown(p) ? 0.0f : 1.0f - p;
    }
  }
  cv::Mat blurred, log;
  cv::GaussianBlur(remapped, blurred, cv::Size(5, 5), 1.0);
  cv::Laplacian(blurred, log, CV_32F, 3);
  double max_abs = 0.0;
  cv::minMaxLoc(cv::abs(log), nullptr, &max_abs);
  const cv::Mat mask = cv::abs(log) > 0.1 * max_abs;
  cv::Mat labels, stats, centroids;
  cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  cv::Mat cleaned = cv::Mat::zeros(log.size(), CV_32FC1);
  for (int r = 0; r < log.rows; ++r) {
    for (int c = 0; c < log.cols; ++c) {
      const int label = labels.at<int>(r, c);
      if (label > 0 && stats.at<int>(label, cv::CC_STAT_AREA) >= 5) cleaned.at<float>(r, c) = log.at<float>(r, c);
    }
  }
  return cleaned;
}

TEST(HarrisCornersTest, EqualsGoodFeaturesToTrackOnReferenceMaps) {
  SLAMSWEEP_REQUIRE_SHARED(json, "reference/maps/expected_paper_metrics.json");
  for (const std::string& name : testing::ReferenceMapNames()) {
    SCOPED_TRACE(name);
    const cv::Mat cleaned = CleanedLog(testing::LoadReferencePgm(json.parent_path() / name));
    const HarrisSelectionOptions options;
    const std::vector<CornerCell> expected = Direct(cleaned, options);
    EXPECT_EQ(static_cast<std::int64_t>(expected.size()),
              testing::ExpectedPaperMetrics(json, name).at("corners").get<std::int64_t>());
    ExpectSameCorners(FindHarrisCorners(cleaned, options), expected);
  }
}

// Mostly-zero images of awkward sizes with scattered structure: tiles, partial last tiles,
// the full-width last band and the small-image path all get exercised.
TEST(HarrisCornersTest, EqualsGoodFeaturesToTrackOnSparseRandomImages) {
  cv::RNG rng(31337);
  for (int trial = 0; trial < 40; ++trial) {
    const int rows = trial < 5 ? rng.uniform(8, 128) : rng.uniform(128, 400);
    const int cols = trial < 5 ? rng.uniform(8, 300) : rng.uniform(128, 400);
    cv::Mat image = cv::Mat::zeros(rows, cols, CV_32FC1);
    const int shapes = rng.uniform(1, 12);
    for (int s = 0; s < shapes; ++s) {
      const cv::Point a(rng.uniform(0, cols), rng.uniform(0, rows));
      const cv::Point b(rng.uniform(0, cols), rng.uniform(0, rows));
      const double value = rng.uniform(-3.0, 3.0);
      if (s % 3 == 0) {
        cv::rectangle(image, a, b, cv::Scalar(value), rng.uniform(1, 4));
      } else if (s % 3 == 1) {
        cv::line(image, a, b, cv::Scalar(value), rng.uniform(1, 3));
      } else {
        cv::circle(image, a, rng.uniform(2, 30), cv::Scalar(value), -1);
      }
    }
    HarrisSelectionOptions options;
    if (trial % 4 == 1) options.block_size_cells = 3;
    if (trial % 4 == 2) options.aperture_cells = 5;
    if (trial % 4 == 3) options.min_distance_cells = 0.5;  // no distance grid at all
    SCOPED_TRACE("trial " + std::to_string(trial) + ": " + std::to_string(rows) + " x " + std::to_string(cols));
    const std::vector<CornerCell> expected = Direct(image, options);
    ExpectSameCorners(FindHarrisCorners(image, options), expected);
    // The same with the non-zero pixels given as runs instead of found by a scan.
    RowRuns nonzero(cols, rows);
    for (int r = 0; r < rows; ++r) AppendNonZeroRuns(image.ptr<float>(r), cols, nonzero);
    ExpectSameCorners(FindHarrisCorners(image, options, &nonzero), expected);
  }
}

TEST(HarrisCornersTest, AllZeroImageHasNoCorners) {
  EXPECT_TRUE(FindHarrisCorners(cv::Mat::zeros(300, 200, CV_32FC1), {}).empty());
  EXPECT_TRUE(FindHarrisCorners(cv::Mat::zeros(3, 3, CV_32FC1), {}).empty());
  EXPECT_TRUE(FindHarrisCorners(cv::Mat(0, 0, CV_32FC1), {}).empty());
}

}  // namespace
}  // namespace slamsweep::evaluator
