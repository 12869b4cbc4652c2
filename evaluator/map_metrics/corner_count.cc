#include "evaluator/map_metrics/corner_count.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>
#include <string>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "evaluator/core/input_error.h"
#include "evaluator/map_metrics/harris_corners.h"
#include "evaluator/map_metrics/laplacian_of_gaussian.h"
#include "evaluator/map_metrics/run_components.h"
#include "evaluator/map_metrics/zero_scan.h"

// The spec leaves the image types open. Everything here is 32-bit float: the remapped image,
// the Gaussian blur, the Laplacian (CV_32F) and the structure threshold, compared in float as
// cv::compare does; goodFeaturesToTrack accepts only 8-bit or float images, so a float pipeline
// never converts. Blobs are 8-connected components of the mask, sized by their number of cells
// (as connectedComponentsWithStats' CC_STAT_AREA), not by contour area: only this reproduces the
// reference counts exactly (fastslam_thirdparty 1051, telecom_icp 2681, telecom_rbpf 1125).

namespace slamsweep::evaluator::inline map_metrics {
namespace {

[[noreturn]] void FailOption(const std::string& name, double value, const std::string& expected) {
  std::ostringstream message;
  message << "option corners." << name << " = " << value << ": expected " << expected;
  throw InputError(message.str());
}

bool OddIn(int value, int low, int high) { return value >= low && value <= high && value % 2 == 1; }

// Keeps the pixels of one block of n <= 32 with |v| > threshold, zeroes the others (to +0,
// as `|v| > t ? v : 0` does) and returns the kept ones as a bit mask. With SSE2 four pixels
// take one compare, and movemask hands over the bits directly: thresholding and finding the
// runs become one pass over the image instead of two.
std::uint32_t KeepAboveInBlock(float* pixels, int n, float threshold) {
  std::uint32_t kept = 0;
  int k = 0;
#if defined(__SSE2__)
  const __m128 magnitude_bits = _mm_castsi128_ps(_mm_set1_epi32(0x7FFFFFFF));
  const __m128 limit = _mm_set1_ps(threshold);
  for (; k + 4 <= n; k += 4) {
    const __m128 v = _mm_loadu_ps(pixels + k);
    const __m128 keep = _mm_cmpgt_ps(_mm_and_ps(v, magnitude_bits), limit);  // false for NaN, as `>`
    _mm_storeu_ps(pixels + k, _mm_and_ps(v, keep));
    kept |= static_cast<std::uint32_t>(_mm_movemask_ps(keep)) << k;
  }
#endif
  for (; k < n; ++k) {
    const bool keep = std::abs(pixels[k]) > threshold;
    pixels[k] = keep ? pixels[k] : 0.0f;
    kept |= static_cast<std::uint32_t>(keep) << k;
  }
  return kept;
}

// Zeroes the LoG outside the structure mask and returns the mask as runs. A kept pixel has
// |v| > threshold >= 0, so it is non-zero: the runs are also those of the non-zero pixels.
RowRuns KeepStructureMask(cv::Mat& log, float threshold) {
  RowRuns runs(log.cols, log.rows);
  for (int row = 0; row < log.rows; ++row) {
    float* pixels = log.ptr<float>(row);
    AppendRunsFromMasks(log.cols, runs,
                        [&](int block, int n) { return KeepAboveInBlock(pixels + block, n, threshold); });
  }
  return runs;
}

}  // namespace

void Validate(const CornerCountOptions& o) {
  if (!OddIn(o.gaussian_kernel_cells, 1, 31))
    FailOption("gaussian_kernel_cells", o.gaussian_kernel_cells, "an odd size in 1..31");
  if (!(o.gaussian_sigma_cells > 0.0) || !std::isfinite(o.gaussian_sigma_cells)) {
    FailOption("gaussian_sigma_cells", o.gaussian_sigma_cells, "a finite sigma > 0");
  }
  if (!OddIn(o.laplacian_kernel_cells, 1, 31))
    FailOption("laplacian_kernel_cells", o.laplacian_kernel_cells, "an odd size in 1..31");
  if (!(o.structure_fraction >= 0.0 && o.structure_fraction < 1.0)) {
    FailOption("structure_fraction", o.structure_fraction, "a fraction in [0, 1)");
  }
  if (o.min_blob_cells < 1) FailOption("min_blob_cells", static_cast<double>(o.min_blob_cells), "at least 1 cell");
  if (o.harris_block_cells < 1 || o.harris_block_cells > 32)
    FailOption("harris_block_cells", o.harris_block_cells, "a block size in 1..32");
  if (!OddIn(o.harris_aperture_cells, 1, 7))
    FailOption("harris_aperture_cells", o.harris_aperture_cells, "a Sobel aperture of 1, 3, 5 or 7");
  if (!std::isfinite(o.harris_k)) FailOption("harris_k", o.harris_k, "a finite number");
  if (!(o.quality_level > 0.0 && o.quality_level <= 1.0))
    FailOption("quality_level", o.quality_level, "a fraction in (0, 1]");
  if (!(o.min_distance_cells >= 0.0) || !std::isfinite(o.min_distance_cells)) {
    FailOption("min_distance_cells", o.min_distance_cells, "a finite distance >= 0");
  }
}

CornerCount ComputeCornerCount(const OccupancyGrid& grid, const CornerCountOptions& options) {
  Validate(options);
  return ComputeCornerCount(ScorableGrid::Check(grid), options);
}

namespace {

LaplacianOfGaussianOptions LaplacianOptions(const CornerCountOptions& options) {
  return {options.gaussian_kernel_cells, options.gaussian_sigma_cells, options.laplacian_kernel_cells};
}

/// The count from the structure image (which it changes).
CornerCount CountCorners(LaplacianOfGaussianImage& laplacian, const CornerCountOptions& options) {
  CornerCount result;
  cv::Mat& log = laplacian.image;
  const float max_abs = laplacian.max_abs;
  result.max_abs_log = max_abs;
  // The threshold is a float, as when cv::compare tests a float image against a scalar.
  const float threshold = static_cast<float>(options.structure_fraction * static_cast<double>(max_abs));
  const RowRuns mask = KeepStructureMask(log, threshold);
  const RunComponentLabels blobs = LabelRunComponents(mask);
  for (const RunComponent& blob : blobs.components) {
    if (blob.cells >= options.min_blob_cells) {
      ++result.structure_blobs_kept;
      result.structure_cells += blob.cells;
    } else {
      ++result.structure_blobs_dropped;
    }
  }
  for (int row = 0; row < mask.height(); ++row) {
    float* pixels = log.ptr<float>(row);
    for (int run = mask.row_first_run(row); run < mask.row_end_run(row); ++run) {
      if (blobs.components[blobs.component_of_run[run]].cells >= options.min_blob_cells) continue;
      std::fill(pixels + mask.begin_col(run), pixels + mask.end_col(run), 0.0f);
    }
  }

  const HarrisSelectionOptions harris{options.harris_block_cells, options.harris_aperture_cells, options.harris_k,
                                      options.quality_level, options.min_distance_cells};
  result.corners = static_cast<std::int64_t>(FindHarrisCorners(log, harris, &mask).size());
  return result;
}

}  // namespace

CornerCount ComputeCornerCount(const ScorableGrid& scorable, const CornerCountOptions& options) {
  Validate(options);
  LaplacianOfGaussianImage laplacian = LaplacianOfGaussian(scorable.grid(), LaplacianOptions(options));
  return CountCorners(laplacian, options);
}

CornerCount ComputeCornerCount(ScorableGrid scorable, OccupancyGrid&& grid, const CornerCountOptions& options) {
  if (&scorable.grid() != &grid) throw std::logic_error("ComputeCornerCount: the grid is not the one checked");
  Validate(options);
  LaplacianOfGaussianImage laplacian = LaplacianOfGaussian(std::move(grid), LaplacianOptions(options));
  return CountCorners(laplacian, options);
}

void to_json(nlohmann::json& out, const CornerCountOptions& o) {
  out = nlohmann::json{{"gaussian_kernel_cells", o.gaussian_kernel_cells},
                       {"gaussian_sigma_cells", o.gaussian_sigma_cells},
                       {"laplacian_kernel_cells", o.laplacian_kernel_cells},
                       {"structure_fraction", o.structure_fraction},
                       {"min_blob_cells", o.min_blob_cells},
                       {"harris_block_cells", o.harris_block_cells},
                       {"harris_aperture_cells", o.harris_aperture_cells},
                       {"harris_k", o.harris_k},
                       {"quality_level", o.quality_level},
                       {"min_distance_cells", o.min_distance_cells}};
}

void to_json(nlohmann::json& out, const CornerCount& result) {
  out = nlohmann::json{{"corners", result.corners},
                       {"max_abs_log", result.max_abs_log},
                       {"structure_blobs_kept", result.structure_blobs_kept},
                       {"structure_blobs_dropped", result.structure_blobs_dropped},
                       {"structure_cells", result.structure_cells}};
}

}  // namespace slamsweep::evaluator::inline map_metrics
