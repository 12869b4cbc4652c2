#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "evaluator/map_metrics/run_components.h"

namespace slamsweep::evaluator::inline map_metrics {

class TileGrid;

/// Parameters of cv::cornerHarris.
struct HarrisResponseOptions {
  int block_size_cells = 2;
  int aperture_cells = 3;
  double harris_k = 0.04;
};

/// One band of whole rows of the Harris response.
struct HarrisResponseBand {
  /// Image row of the band's first row.
  int first_row = 0;
  /// rows x image.cols, CV_32FC1, zero outside `computed_areas`.
  cv::Mat response;
  /// The areas (in image coordinates, inside the band) where the response was computed.
  std::vector<cv::Rect> computed_areas;
};

/// The Harris response cv::cornerHarris(image, ..., BORDER_DEFAULT) computes for a CV_32FC1
/// image, computed only where it can be non-zero and cut into bands of whole rows, top to
/// bottom, every row in exactly one band: for an image that is zero on most of its area (the corner count's
/// cleaned structure image) that is a fraction of the work, and the memory is a few bands
/// instead of a full-size response (the whole-image call also holds Dx, Dy and a 3-channel
/// covariance image at once).
///
/// The image is cut into 64 x 64 tiles; a tile is computed when a non-zero pixel lies within
/// reach of its response (derivative radius + block size), consecutive such tiles of a tile
/// row in one cornerHarris call on the sub-image widened by a margin (cornerHarris reads the
/// real pixels around a sub-image for its derivatives but reflects its block sum at the
/// sub-image's edge; the margin absorbs that and is thrown away). Elsewhere the response is 0,
/// which is what an all-zero neighbourhood gives. A band is one tile row (the last one absorbs
/// the remainder); small images are one band computed whole.
///
/// With the corner count's 2 x 2 block, each call's response comes from HarrisResponseOfArea
/// (harris_area.h), equal bit for bit to cv::cornerHarris on the same area; other blocks call it.
///
/// Exactness: per pixel the same arithmetic runs as in the whole-image call, with one caveat.
/// OpenCV's block sum keeps double-precision running sums that start at each call's first row
/// and column, so a computed response can differ from the whole-image call in its last bits
/// (and the whole-image call leaves sub-1e-30 residues where this gives 0). Only an exact tie
/// could turn that into a different corner; tests compare the corner lists.
///
/// `nonzero`, when given, holds runs covering every non-zero pixel of the image (it may cover
/// zeros too); it saves a scan of the image. Compute(i) is a pure function of the band's index:
/// bands may be computed in any order, on any thread (the image must outlive this object).
class HarrisResponseBands {
 public:
  HarrisResponseBands(const cv::Mat& image, const HarrisResponseOptions& options, const RowRuns* nonzero);
  /// Number of bands (0 for an empty image).
  int count() const;
  /// Band `index` (0 .. count() - 1), top to bottom.
  HarrisResponseBand Compute(int index) const;

 private:
  cv::Mat image_;
  HarrisResponseOptions options_;
  bool whole_ = true;                      // a small image: one band, one cornerHarris call
  std::shared_ptr<const TileGrid> tiles_;  // which tiles need computing
};

}  // namespace slamsweep::evaluator::inline map_metrics
