#include "evaluator/map_metrics/laplacian_of_gaussian.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <opencv2/imgproc.hpp>

#include "evaluator/core/huge_pages.h"
#include "evaluator/map_metrics/zero_scan.h"

namespace slamsweep::evaluator::inline map_metrics {
namespace {

// 64 rows of a 2000-cell map are 0.5 MB per float band: the remapped and blurred bands stay
// in L2 between the two filters.
constexpr int kBandRows = 64;
constexpr int kMinBandedWidth = 16;

// Rows [row_begin, row_end) of the remapped image into `out`: known cells 1 - p, unknown 0.
// Written as a bit mask rather than a conditional so that the compiler vectorises it (it may
// not speculate 1 - p past a branch).
void RemapRows(const OccupancyGrid& grid, int row_begin, int row_end, cv::Mat& out) {
  out.create(row_end - row_begin, grid.width, CV_32FC1);
  const float* cells = grid.cells.data() + static_cast<std::size_t>(row_begin) * grid.width;
  float* remapped = out.ptr<float>(0);
  const std::size_t n = static_cast<std::size_t>(row_end - row_begin) * grid.width;
  for (std::size_t i = 0; i < n; ++i) {
    const float p = cells[i];
    const std::uint32_t keep = 0u - static_cast<std::uint32_t>(p >= 0.0f);
    remapped[i] = std::bit_cast<float>(std::bit_cast<std::uint32_t>(1.0f - p) & keep);
  }
}

/// Runs the banded filters over `grid`. Band k's result goes into target(first row, rows), and
/// finished(first row, that image) is called once band k + 1 has taken its remapped rows from the
/// grid (or at the end): from then on no band reads band k's rows of the grid.
template <typename Target, typename Finished>
float FilterInBands(const OccupancyGrid& grid, const LaplacianOfGaussianOptions& options, Target&& target,
                    Finished&& finished) {
  const int height = grid.height;
  // Rows each filter reads beyond the rows it computes (a 1-cell Laplacian is a 3 x 3 kernel).
  const int blur_reach = options.gaussian_kernel_cells / 2;
  const int laplacian_reach = std::max(1, options.laplacian_kernel_cells / 2);
  const cv::Size gaussian_size(options.gaussian_kernel_cells, options.gaussian_kernel_cells);

  // OpenCV's filters take another path on single-column images, whose results depend on the
  // height: narrow maps (cheap anyway) are filtered as one band.
  const int band_rows = grid.width < kMinBandedWidth ? height : kBandRows;

  float max_abs = 0.0f;
  cv::Mat remapped;  // reused by every band
  cv::Mat blurred;
  cv::Mat band;
  int band_begin = -1;
  for (int row_begin = 0; row_begin < height; row_begin += band_rows) {
    const int row_end = std::min(height, row_begin + band_rows);
    // Blurred rows the Laplacian reads, and remapped rows the blur reads for those.
    const int blurred_begin = std::max(0, row_begin - laplacian_reach);
    const int blurred_end = std::min(height, row_end + laplacian_reach);
    const int remapped_begin = std::max(0, blurred_begin - blur_reach);
    const int remapped_end = std::min(height, blurred_end + blur_reach);

    RemapRows(grid, remapped_begin, remapped_end, remapped);
    if (band_begin >= 0) finished(band_begin, band);
    cv::GaussianBlur(remapped.rowRange(blurred_begin - remapped_begin, blurred_end - remapped_begin), blurred,
                     gaussian_size, options.gaussian_sigma_cells, options.gaussian_sigma_cells, cv::BORDER_DEFAULT);
    band = target(row_begin, row_end - row_begin);  // written in place: same size and type
    cv::Laplacian(blurred.rowRange(row_begin - blurred_begin, row_end - blurred_begin), band, CV_32F,
                  options.laplacian_kernel_cells, 1.0, 0.0, cv::BORDER_DEFAULT);
    max_abs = std::max(max_abs, MaxAbs(band.ptr<float>(0), band.total()));
    band_begin = row_begin;
  }
  if (band_begin >= 0) finished(band_begin, band);
  return max_abs;
}

}  // namespace

LaplacianOfGaussianImage LaplacianOfGaussian(const OccupancyGrid& grid, const LaplacianOfGaussianOptions& options) {
  LaplacianOfGaussianImage result;
  result.image.create(grid.height, grid.width, CV_32FC1);
  AdviseHugePages(result.image.data, result.image.total() * sizeof(float));  // before its first write
  result.max_abs = FilterInBands(
      grid, options, [&](int first_row, int rows) { return result.image.rowRange(first_row, first_row + rows); },
      [](int, const cv::Mat&) {});
  return result;
}

LaplacianOfGaussianImage LaplacianOfGaussian(OccupancyGrid&& grid, const LaplacianOfGaussianOptions& options) {
  LaplacianOfGaussianImage result;
  float* const cells = grid.cells.data();
  const std::size_t width = static_cast<std::size_t>(grid.width);
  cv::Mat scratch;  // one band, until its rows of the grid are no longer read
  result.max_abs = FilterInBands(
      grid, options,
      [&](int, int rows) {
        scratch.create(rows, grid.width, CV_32FC1);
        return scratch;
      },
      [&](int first_row, const cv::Mat& band) {
        band.copyTo(cv::Mat(band.rows, band.cols, CV_32FC1, cells + static_cast<std::size_t>(first_row) * width));
      });
  result.storage = std::move(grid.cells);  // the data stays where it is
  result.image = cv::Mat(grid.height, grid.width, CV_32FC1, result.storage.data());
  return result;
}

}  // namespace slamsweep::evaluator::inline map_metrics
