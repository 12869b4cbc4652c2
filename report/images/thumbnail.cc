#include "report/images/thumbnail.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/image_file.h"
#include "report/images/area_shrink.h"
#include "report/images/map_greys.h"

namespace slamsweep::report::inline images {
namespace {

cv::Mat GreyOf(const cv::Mat& image) {
  if (image.channels() == 1) return image;
  cv::Mat grey;
  // ReadImageFile gives R, G, B(, A), not OpenCV's usual B, G, R.
  cv::cvtColor(image, grey, image.channels() == 4 ? cv::COLOR_RGBA2GRAY : cv::COLOR_RGB2GRAY);
  return grey;
}

/// The bounding box of the known part of the map, with a margin, or the whole image.
cv::Rect KnownArea(const cv::Mat& grey) {
  cv::Mat known = grey != kUnknownGrey;
  const cv::Rect box = cv::boundingRect(known);
  if (box.empty()) return {0, 0, grey.cols, grey.rows};
  const int margin = std::max(2, static_cast<int>(0.04 * std::max(grey.cols, grey.rows)));
  const cv::Rect padded(box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin);
  return padded & cv::Rect(0, 0, grey.cols, grey.rows);
}

}  // namespace

void WriteThumbnail(const std::filesystem::path& map_image, const std::filesystem::path& png, int max_side_px) {
  if (max_side_px < 1) {
    throw evaluator::InputError("thumbnail max_side_px: expected at least 1 pixel, got " + std::to_string(max_side_px));
  }
  const cv::Mat grey = GreyOf(evaluator::ReadImageFile(map_image));
  cv::Mat thumbnail = grey(KnownArea(grey));
  thumbnail = ShrinkToFit(thumbnail, max_side_px);
  evaluator::WriteBinaryFile(png, evaluator::EncodePng(thumbnail.clone()));
}

}  // namespace slamsweep::report::inline images
