#pragma once

#include <opencv2/core/mat.hpp>

namespace slamsweep::report::inline images {

/// The size of `size` shrunk so that its longer side is at most `max_side_px` (never enlarged;
/// each side at least 1 pixel).
cv::Size ShrunkSize(const cv::Size& size, int max_side_px);

/// `image` reduced to `size` (no larger than the image on either side) by area averaging.
/// OpenCV's INTER_AREA is fast for integer factors and many times slower otherwise, so the
/// image is first reduced by the largest integer factor that keeps it at least `size` (exact
/// block averages), then by the remaining factor below 2: bilinear when it is at most 1.25 (no
/// pixel can fall between samples), INTER_AREA otherwise. The result differs from a one-step
/// INTER_AREA by a few grey levels at most along edges; maps look the same, thin walls included.
cv::Mat ShrinkByArea(const cv::Mat& image, const cv::Size& size);

/// ShrinkByArea to ShrunkSize(image.size(), max_side_px); the image itself when it already fits.
cv::Mat ShrinkToFit(const cv::Mat& image, int max_side_px);

}  // namespace slamsweep::report::inline images
