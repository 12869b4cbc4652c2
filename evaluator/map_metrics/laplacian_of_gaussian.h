#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::evaluator::inline map_metrics {

struct LaplacianOfGaussianOptions {
  int gaussian_kernel_cells = 5;  // odd
  double gaussian_sigma_cells = 1.0;
  int laplacian_kernel_cells = 3;  // odd
};

struct LaplacianOfGaussianImage {
  /// CV_32FC1, grid.height x grid.width, continuous.
  cv::Mat image;
  /// Largest |value| of `image`.
  float max_abs = 0.0f;
  /// The memory `image` lies in when it reuses a grid's cells (empty otherwise).
  std::vector<float> storage;
};

/// The corner count's structure image: the grid remapped (known cells 1 - p, unknown 0),
/// blurred with cv::GaussianBlur and filtered with cv::Laplacian (CV_32F, BORDER_DEFAULT),
/// equal bit for bit to running the two filters on the whole remapped image.
///
/// It is computed in bands of rows: each band is remapped and blurred with just the rows the
/// two kernels reach beyond it, so that only the result is a full-size image. Besides saving
/// two full-size float images (and the page faults of fresh memory), a band stays in cache
/// from the remap to the Laplacian. OpenCV's filters read the real rows around a sub-image
/// and extrapolate the border only at the edges of its parent buffer, which coincide with the
/// image's edges or lie beyond the kernels' reach; bands span whole rows, so every pixel sees
/// the same inputs in the same order as in the whole-image call.
LaplacianOfGaussianImage LaplacianOfGaussian(const OccupancyGrid& grid, const LaplacianOfGaussianOptions& options);

/// The same image written over the cells of a grid that is no longer needed, instead of into a
/// new full-size image: each band is written back only after the next band has copied the rows
/// it reads, which the kernels' reach (less than a band) guarantees are the last ones it needs.
LaplacianOfGaussianImage LaplacianOfGaussian(OccupancyGrid&& grid, const LaplacianOfGaussianOptions& options);

}  // namespace slamsweep::evaluator::inline map_metrics
