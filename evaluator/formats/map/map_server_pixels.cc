#include "evaluator/formats/map/map_server_pixels.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <optional>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline map {

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

namespace {

[[noreturn]] void ThrowRawValue(const MapServerMetadata& metadata, int row, int col, std::uint8_t value) {
  throw InputError(
      Located(metadata.image, 0,
              fmt::format("raw mode: pixel (row {}, column {}) has value {}; raw map values are 0..100 (occupancy "
                          "percent) or 255 (unknown){}",
                          row, col, value, metadata.negate ? " after negate" : "")));
}

/// The cell of a map_server value (MapServerPixelValue), or nullopt for a raw value without meaning.
std::optional<float> CellOf(std::uint8_t value) {
  if (value == kMapServerUnknownByte) return OccupancyGrid::kUnknown;
  if (value <= 100) return static_cast<float>(value / 100.0);
  return std::nullopt;
}

}  // namespace

OccupancyGrid MapServerGridFromImage(const cv::Mat& image, const MapServerMetadata& metadata) {
  const int channels = image.channels();
  if (image.empty() || image.depth() != CV_8U || (channels != 1 && channels != 3 && channels != 4)) {
    throw InputError(Located(metadata.image, 0, "expected an 8-bit grey, RGB or RGBA image"));
  }
  OccupancyGrid grid(image.cols, image.rows, metadata.resolution_m, metadata.origin);
  if (channels == 1) {
    // A grey pixel's cell depends on its value alone: the 256 answers are worked out once.
    std::array<float, 256> cell_of_grey{};
    std::array<bool, 256> meaningful{};
    for (int grey = 0; grey < 256; ++grey) {
      const auto sample = static_cast<std::uint8_t>(grey);
      const std::optional<float> cell = CellOf(MapServerPixelValue(&sample, 1, metadata));
      meaningful[static_cast<std::size_t>(grey)] = cell.has_value();
      cell_of_grey[static_cast<std::size_t>(grey)] = cell.value_or(OccupancyGrid::kUnknown);
    }
    // Only raw mode has values without a meaning; then the pixels are checked, in order.
    const bool all_meaningful = std::all_of(meaningful.begin(), meaningful.end(), [](bool ok) { return ok; });
    for (int row = 0; row < image.rows; ++row) {
      const std::uint8_t* pixel = image.ptr<std::uint8_t>(row);
      float* cells = grid.cells.data() + static_cast<std::size_t>(row) * static_cast<std::size_t>(image.cols);
      for (int col = 0; col < image.cols; ++col) cells[col] = cell_of_grey[pixel[col]];
      if (all_meaningful) continue;
      for (int col = 0; col < image.cols; ++col) {
        if (!meaningful[pixel[col]]) ThrowRawValue(metadata, row, col, MapServerPixelValue(pixel + col, 1, metadata));
      }
    }
    return grid;
  }
  for (int row = 0; row < image.rows; ++row) {
    const std::uint8_t* pixel = image.ptr<std::uint8_t>(row);
    for (int col = 0; col < image.cols; ++col, pixel += channels) {
      const std::uint8_t value = MapServerPixelValue(pixel, channels, metadata);
      const std::optional<float> cell = CellOf(value);
      if (!cell) ThrowRawValue(metadata, row, col, value);
      grid.at(row, col) = *cell;
    }
  }
  return grid;
}

}  // namespace slamsweep::evaluator::inline formats::inline map
