#include "evaluator/formats/map/map_server_pixels.h"

#include <fmt/format.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {

std::uint8_t MapServerPixelValue(const std::uint8_t* samples, int channels, const MapServerMetadata& metadata) {
  const bool has_alpha = channels == 4;
  const int averaged = (metadata.mode == MapServerMode::kTrinary || !has_alpha) ? channels : channels - 1;
  int sum = 0;
  for (int k = 0; k < averaged; ++k) sum += samples[k];
  double average = sum / static_cast<double>(averaged);
  const int alpha = channels == 1 ? 1 : samples[channels - 1];
  if (metadata.negate) average = 255.0 - average;
  // map_server assigns these doubles to an unsigned char: truncation toward zero.
  if (metadata.mode == MapServerMode::kRaw) return static_cast<std::uint8_t>(average);

  const double occupancy = (255.0 - average) / 255.0;
  if (occupancy > metadata.occupied_thresh) return 100;
  if (occupancy < metadata.free_thresh) return 0;
  if (metadata.mode == MapServerMode::kTrinary || alpha < 1) return kMapServerUnknownByte;
  const double ratio = (occupancy - metadata.free_thresh) / (metadata.occupied_thresh - metadata.free_thresh);
  return static_cast<std::uint8_t>(99.0 * ratio);
}

OccupancyGrid MapServerGridFromImage(const cv::Mat& image, const MapServerMetadata& metadata) {
  const int channels = image.channels();
  if (image.empty() || image.depth() != CV_8U || (channels != 1 && channels != 3 && channels != 4)) {
    throw InputError(Located(metadata.image, 0, "expected an 8-bit grey, RGB or RGBA image"));
  }
  OccupancyGrid grid(image.cols, image.rows, metadata.resolution_m, metadata.origin);
  for (int row = 0; row < image.rows; ++row) {
    const std::uint8_t* pixel = image.ptr<std::uint8_t>(row);
    for (int col = 0; col < image.cols; ++col, pixel += channels) {
      const std::uint8_t value = MapServerPixelValue(pixel, channels, metadata);
      if (value == kMapServerUnknownByte) {
        grid.at(row, col) = OccupancyGrid::kUnknown;
      } else if (value <= 100) {
        grid.at(row, col) = static_cast<float>(value / 100.0);
      } else {
        throw InputError(Located(
            metadata.image, 0,
            fmt::format("raw mode: pixel (row {}, column {}) has value {}; raw map values are 0..100 (occupancy "
                        "percent) or 255 (unknown){}",
                        row, col, value, metadata.negate ? " after negate" : "")));
      }
    }
  }
  return grid;
}

}  // namespace slamsweep::evaluator
