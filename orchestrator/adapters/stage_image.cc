#include "orchestrator/adapters/stage_image.h"

#include <cmath>
#include <cstdint>

#include "evaluator/formats/map/map_options.h"

namespace slamsweep::orchestrator {

cv::Mat StageImage(const evaluator::OccupancyGrid& grid) {
  const evaluator::MapWriteOptions thresholds;
  cv::Mat image(grid.height, grid.width, CV_8UC1, cv::Scalar(kStageUnknown));
  for (int row = 0; row < grid.height; ++row) {
    auto* out = image.ptr<std::uint8_t>(row);
    for (int col = 0; col < grid.width; ++col) {
      const float p = grid.at(row, col);
      if (evaluator::OccupancyGrid::IsUnknown(p)) continue;
      const long percent = std::lround(100.0 * p);
      if (percent >= thresholds.occupied_threshold_percent) {
        out[col] = kStageOccupied;
      } else if (percent <= thresholds.free_threshold_percent) {
        out[col] = kStageFree;
      }
    }
  }
  return image;
}

}  // namespace slamsweep::orchestrator
