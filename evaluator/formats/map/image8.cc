#include "evaluator/formats/map/image8.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline map {
namespace {

void RequireGreyLevel(int value, const char* name) {
  if (value < 0 || value > 255) throw InputError(fmt::format("{}: expected a grey level 0..255, got {}", name, value));
}

}  // namespace

void RequireValidGrid(const OccupancyGrid& grid) {
  if (grid.width <= 0 || grid.height <= 0 ||
      grid.cells.size() != static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height)) {
    throw InputError(fmt::format("grid of {} x {} cells holds {} values; expected a positive width x height",
                                 grid.width, grid.height, grid.cells.size()));
  }
  for (std::size_t i = 0; i < grid.cells.size(); ++i) {
    const float p = grid.cells[i];
    if (!OccupancyGrid::IsUnknown(p) && !(p <= 1.0f)) {  // the negated test also catches NaN
      throw InputError(fmt::format("grid cell (row {}, column {}) holds {}; expected p in [0, 1] or unknown",
                                   i / static_cast<std::size_t>(grid.width), i % static_cast<std::size_t>(grid.width),
                                   p));
    }
  }
}

cv::Mat ToImage8(const OccupancyGrid& grid, int unknown_value) {
  RequireGreyLevel(unknown_value, "unknown_value");
  RequireValidGrid(grid);
  cv::Mat image(grid.height, grid.width, CV_8UC1);
  for (int row = 0; row < grid.height; ++row) {
    std::uint8_t* out = image.ptr<std::uint8_t>(row);
    for (int col = 0; col < grid.width; ++col) {
      const float p = grid.at(row, col);
      out[col] = OccupancyGrid::IsUnknown(p)
                     ? static_cast<std::uint8_t>(unknown_value)
                     : static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - static_cast<double>(p))));
    }
  }
  return image;
}

OccupancyGrid FromImage8(const cv::Mat& image8, std::optional<int> unknown_value, double resolution_m,
                         GridOrigin origin) {
  if (image8.empty() || image8.type() != CV_8UC1) {
    throw InputError("FromImage8: expected a non-empty 8-bit single-channel image");
  }
  if (unknown_value) RequireGreyLevel(*unknown_value, "unknown_value");
  if (!std::isfinite(resolution_m) || resolution_m <= 0.0) {
    throw InputError(fmt::format("resolution: expected a positive number of metres per cell, got {}", resolution_m));
  }
  OccupancyGrid grid(image8.cols, image8.rows, resolution_m, origin);
  for (int row = 0; row < image8.rows; ++row) {
    const std::uint8_t* in = image8.ptr<std::uint8_t>(row);
    for (int col = 0; col < image8.cols; ++col) {
      const int value = in[col];
      grid.at(row, col) = (unknown_value && value == *unknown_value) ? OccupancyGrid::kUnknown
                                                                     : static_cast<float>((255 - value) / 255.0);
    }
  }
  return grid;
}

}  // namespace slamsweep::evaluator::inline formats::inline map
