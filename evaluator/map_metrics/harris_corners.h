#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "evaluator/map_metrics/run_components.h"
#include "evaluator/map_metrics/sparse_harris_response.h"

namespace slamsweep::evaluator::inline map_metrics {

/// The parameters of cv::goodFeaturesToTrack with the Harris detector, without a corner limit
/// or a mask (the paper's corner count keeps every corner).
struct HarrisSelectionOptions {
  int block_size_cells = 2;
  int aperture_cells = 3;
  double harris_k = 0.04;
  double quality_level = 0.01;
  double min_distance_cells = 10.0;
};

struct CornerCell {
  int row = 0;
  int col = 0;
};

/// The corners that cv::goodFeaturesToTrack(image, corners, 0, quality_level, min_distance_cells,
/// noArray(), block_size_cells, aperture_cells, true, harris_k) returns, in the same order, for
/// a CV_32FC1 image.
///
/// Why not call it: on a 2000 x 2000 grid it holds about seven float images at once (Dx, Dy,
/// the 3-channel covariance, the response and its dilation, ~110 MB) and computes the Harris
/// response everywhere, although the cleaned structure image the corner count feeds it is zero
/// on most of the map. Here the response comes from HarrisResponseBands (computed near the
/// structure only, a band of rows at a time, on two threads where two cores are free; see its
/// caveat on exactness) and goodFeaturesToTrack's selection is replayed on the bands: threshold quality_level * max
/// response, local maxima of the 3 x 3 dilation away from the outermost rows and columns, sort by decreasing response
/// with ties broken by decreasing address, and the min-distance grid. Tests check the corner lists against the direct
/// call on the reference maps and on random images.
///
/// `nonzero`, when given, holds runs covering every non-zero pixel of the image (it may cover
/// zeros too); it saves a scan of the image to find where the structure is.
/// Throws cv::Exception for an image that is not CV_32FC1 (callers validate their options).
std::vector<CornerCell> FindHarrisCorners(const cv::Mat& image, const HarrisSelectionOptions& options,
                                          const RowRuns* nonzero = nullptr);

}  // namespace slamsweep::evaluator::inline map_metrics
