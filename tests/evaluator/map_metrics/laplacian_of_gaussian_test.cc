#include "evaluator/map_metrics/laplacian_of_gaussian.h"

#include <gtest/gtest.h>

#include <cstring>
#include <opencv2/imgproc.hpp>
#include <random>

namespace slamsweep::evaluator {
namespace {

// A map with every kind of cell: unknown, free, occupied and grey values, in random places.
OccupancyGrid RandomMap(int rows, int cols, unsigned seed) {
  OccupancyGrid grid(cols, rows, 0.05);
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> probability(0.0f, 1.0f);
  for (float& cell : grid.cells) {
    const unsigned kind = random() % 4;
    cell = kind == 0 ? OccupancyGrid::kUnknown : kind == 1 ? 0.0f : kind == 2 ? 1.0f : probability(random);
  }
  return grid;
}

// The definition, on the whole image at once.
cv::Mat WholeImageLog(const OccupancyGrid& grid, const LaplacianOfGaussianOptions& options) {
  cv::Mat remapped(grid.height, grid.width, CV_32FC1);
  for (int row = 0; row < grid.height; ++row) {
    for (int col = 0; col < grid.width; ++col) {
      const float p = grid.at(row, col);
      remapped.at<float>(row, col) = OccupancyGrid::IsUnknown(p) ? 0.0f : 1.0f - p;
    }
  }
  cv::Mat blurred;
  cv::Mat log;
  cv::GaussianBlur(remapped, blurred, cv::Size(options.gaussian_kernel_cells, options.gaussian_kernel_cells),
                   options.gaussian_sigma_cells, options.gaussian_sigma_cells, cv::BORDER_DEFAULT);
  cv::Laplacian(blurred, log, CV_32F, options.laplacian_kernel_cells, 1.0, 0.0, cv::BORDER_DEFAULT);
  return log;
}

TEST(LaplacianOfGaussianTest, BandsEqualTheWholeImageFiltersBitForBit) {
  // Heights around the band height (64) and below the kernels' reach; widths that leave
  // vector remainders.
  const int heights[] = {1, 2, 7, 63, 64, 65, 129, 200};
  const int widths[] = {1, 3, 37, 130};
  const LaplacianOfGaussianOptions option_sets[] = {{5, 1.0, 3}, {7, 1.5, 5}, {1, 0.5, 1}, {31, 4.0, 31}};
  unsigned seed = 1;
  for (const LaplacianOfGaussianOptions& options : option_sets) {
    for (const int height : heights) {
      for (const int width : widths) {
        SCOPED_TRACE(::testing::Message() << height << " x " << width << ", gaussian " << options.gaussian_kernel_cells
                                          << ", laplacian " << options.laplacian_kernel_cells);
        const OccupancyGrid grid = RandomMap(height, width, seed++);
        const cv::Mat expected = WholeImageLog(grid, options);
        const LaplacianOfGaussianImage actual = LaplacianOfGaussian(grid, options);
        ASSERT_EQ(actual.image.size(), expected.size());
        ASSERT_EQ(actual.image.type(), CV_32FC1);
        ASSERT_TRUE(actual.image.isContinuous());
        EXPECT_EQ(std::memcmp(actual.image.ptr(0), expected.ptr(0), expected.total() * sizeof(float)), 0);
        double expected_max = 0.0;
        cv::minMaxIdx(cv::abs(expected), nullptr, &expected_max);
        EXPECT_EQ(actual.max_abs, static_cast<float>(expected_max));
        // Written over the cells of a copy of the grid, band after band: the same image.
        OccupancyGrid consumed = grid;
        const float* cells = consumed.cells.data();
        const LaplacianOfGaussianImage in_place = LaplacianOfGaussian(std::move(consumed), options);
        ASSERT_EQ(in_place.image.size(), expected.size());
        EXPECT_EQ(in_place.image.ptr<float>(0), cells);  // no new full-size image
        EXPECT_EQ(std::memcmp(in_place.image.ptr(0), expected.ptr(0), expected.total() * sizeof(float)), 0);
        EXPECT_EQ(in_place.max_abs, actual.max_abs);
      }
    }
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
