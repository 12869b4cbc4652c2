#include "slam/slam_toolbox/slam_toolbox_map.h"

#include <memory>

namespace slamsweep::slam::slam_toolbox_driver {

evaluator::OccupancyGrid KartoMap(const karto::LocalizedRangeScanVector& scans, double resolution_m) {
  const std::unique_ptr<karto::OccupancyGrid> grid(karto::OccupancyGrid::CreateFromScans(scans, resolution_m));
  if (grid == nullptr) return evaluator::OccupancyGrid(1, 1, resolution_m);
  const int width = grid->GetWidth();
  const int height = grid->GetHeight();
  // The grid's offset is the world position of its cell (0, 0)'s lower-left corner, as the node's map origin.
  const karto::Vector2<kt_double> offset = grid->GetCoordinateConverter()->GetOffset();
  evaluator::OccupancyGrid map(width, height, resolution_m, {offset.GetX(), offset.GetY(), 0.0});
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const kt_int8u value = grid->GetValue(karto::Vector2<kt_int32s>(x, y));
      float& cell = map.at(height - 1 - y, x);  // grid row y counts up from the bottom; image rows down
      if (value == karto::GridStates_Occupied) {
        cell = 1.0f;
      } else if (value == karto::GridStates_Free) {
        cell = 0.0f;
      }
    }
  }
  return map;
}

}  // namespace slamsweep::slam::slam_toolbox_driver
