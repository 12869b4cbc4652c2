#include "report/images/area_shrink.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace slamsweep::report::inline images {

cv::Size ShrunkSize(const cv::Size& size, int max_side_px) {
  const int side = std::max(size.width, size.height);
  if (side <= max_side_px) return size;
  const double scale = static_cast<double>(max_side_px) / side;
  return {std::max(1, static_cast<int>(std::lround(size.width * scale))),
          std::max(1, static_cast<int>(std::lround(size.height * scale)))};
}

cv::Mat ShrinkByArea(const cv::Mat& image, const cv::Size& size) {
  if (image.size() == size) return image;
  const int factor = std::min(image.cols / size.width, image.rows / size.height);
  cv::Mat reduced = image;
  if (factor >= 2) {
    // Whole blocks of factor x factor pixels: OpenCV's fast path, and exact area averaging. A
    // ragged right or bottom edge is padded by repeating it, so no wall on the border is lost.
    const int pad_right = (factor - image.cols % factor) % factor;
    const int pad_bottom = (factor - image.rows % factor) % factor;
    cv::Mat padded = image;
    if (pad_right > 0 || pad_bottom > 0) {
      cv::copyMakeBorder(image, padded, 0, pad_bottom, 0, pad_right, cv::BORDER_REPLICATE);
    }
    cv::resize(padded, reduced, {padded.cols / factor, padded.rows / factor}, 0, 0, cv::INTER_AREA);
  }
  if (reduced.size() == size) return reduced;
  cv::Mat shrunk;
  // A last step of at most 1.25 is bilinear: samples are at most 1.25 pixels apart, so every pixel
  // (a one-cell wall too) still weighs at least 3/8 in some output pixel, and it costs a fraction
  // of OpenCV's general INTER_AREA. Larger last steps average areas.
  const double last_step =
      std::max(static_cast<double>(reduced.cols) / size.width, static_cast<double>(reduced.rows) / size.height);
  cv::resize(reduced, shrunk, size, 0, 0, last_step <= 1.25 ? cv::INTER_LINEAR : cv::INTER_AREA);
  return shrunk;
}

cv::Mat ShrinkToFit(const cv::Mat& image, int max_side_px) {
  return ShrinkByArea(image, ShrunkSize(image.size(), max_side_px));
}

}  // namespace slamsweep::report::inline images
