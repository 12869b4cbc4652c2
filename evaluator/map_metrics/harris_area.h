#pragma once

#include <opencv2/core.hpp>

namespace slamsweep::evaluator::inline map_metrics {

/// True when HarrisResponseOfArea reproduces cv::cornerHarris for these parameters: a 2 x 2
/// block (the corner count's), any Sobel aperture, on a call area of at least 2 x 2 cells.
bool HarrisAreaSupported(int block_size_cells, cv::Size call_area);

/// Writes into `out` (kept.size(), CV_32FC1) what
/// cv::cornerHarris(image(call_area), response, 2, aperture_cells, harris_k, BORDER_DEFAULT)
/// gives on `kept` (a rectangle inside `call_area`, both in image coordinates), bit for bit,
/// without the full-size temporaries and with the block sum done here instead of by OpenCV's
/// generic filter engine.
///
/// The derivatives are OpenCV's own Sobel calls on `call_area`, as cornerHarris makes them. The
/// 2 x 2 block sum replays OpenCV's box filter for float images exactly: double running sums along
/// each row (the row at the left edge reflected, 101) and down each column (the first row
/// reflected), restarted at the call area's first row and column, rounded to float. The response
/// is cornerHarris's final step on the call area taken as one continuous row: its AVX formula
/// (a*c - b*b) - k*((a + c)^2) in float for the first multiple of 8 cells, its 4-wide formula
/// (a*c - b*b) - (k*(a + c))*(a + c) for the next 4 when there are, and its scalar one (in double
/// for k) for the last cells. Requires HarrisAreaSupported and a CV_32FC1 image.
void HarrisResponseOfArea(const cv::Mat& image, cv::Rect call_area, cv::Rect kept, int aperture_cells, double harris_k,
                          cv::Mat out);

}  // namespace slamsweep::evaluator::inline map_metrics
