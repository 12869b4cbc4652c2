#include "orchestrator/adapters/stage_image.h"

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "evaluator/formats/map/map_options.h"

namespace slamsweep::orchestrator {

namespace {

/// The smallest float p with 100.0 * p >= percent (computed in double, as the rule does): the
/// product is monotonic in p, so comparing p with it decides exactly what comparing the product
/// with `percent` decides.
float SmallestWithPercentAtLeast(double percent) {
  float p = static_cast<float>(percent / 100.0);
  while (100.0 * static_cast<double>(p) < percent) p = std::nextafter(p, 2.0f);
  while (100.0 * static_cast<double>(std::nextafter(p, -1.0f)) >= percent) p = std::nextafter(p, -1.0f);
  return p;
}

}  // namespace

cv::Mat StageImage(const evaluator::OccupancyGrid& grid) {
  const evaluator::MapWriteOptions thresholds;
  // For v = lround(100 p) (halves away from zero): v >= T exactly when 100 p >= T - 0.5, and
  // v <= F exactly when 100 p < F + 0.5, i.e. when p is below the smallest float reaching it. A NaN
  // p rounds to LONG_MIN, i.e. free, and fails `p >= free_from` too. Float comparisons instead of a
  // libm call per cell: the loop vectorises.
  const float occupied_from = SmallestWithPercentAtLeast(thresholds.occupied_threshold_percent - 0.5);
  const float free_from = SmallestWithPercentAtLeast(thresholds.free_threshold_percent + 0.5);
  cv::Mat image(grid.height, grid.width, CV_8UC1);
  const std::size_t width = static_cast<std::size_t>(grid.width);
  for (int row = 0; row < grid.height; ++row) {
    auto* out = image.ptr<std::uint8_t>(row);
    const float* cells = grid.cells.data() + static_cast<std::size_t>(row) * width;
    for (std::size_t col = 0; col < width; ++col) {
      const float p = cells[col];
      std::uint8_t grey = p >= occupied_from ? kStageOccupied : kStageUnknown;
      grey = !(p >= free_from) ? static_cast<std::uint8_t>(kStageFree) : grey;
      out[col] = evaluator::OccupancyGrid::IsUnknown(p) ? static_cast<std::uint8_t>(kStageUnknown) : grey;
    }
  }
  return image;
}

}  // namespace slamsweep::orchestrator
