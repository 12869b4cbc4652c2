#include "slam/hector/hector_map.h"

#include <algorithm>

namespace slamsweep::slam::hector {

evaluator::OccupancyGrid FinestMap(const hectorslam::HectorSlamProcessor& processor) {
  const hectorslam::GridMap& map = processor.getGridMap(0);
  const int size_x = map.getSizeX();
  const int size_y = map.getSizeY();
  const auto updated = [&](int x, int y) { return map.getCell(x, y).getValue() != 0.0f; };
  int x0 = size_x, y0 = size_y, x1 = -1, y1 = -1;
  for (int y = 0; y < size_y; ++y) {
    for (int x = 0; x < size_x; ++x) {
      if (!updated(x, y)) continue;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  }
  if (x1 < 0) x0 = y0 = 0, x1 = y1 = 0;  // nothing mapped yet: one unknown cell
  constexpr int kMargin = 2;
  x0 = std::max(0, x0 - kMargin), y0 = std::max(0, y0 - kMargin);
  x1 = std::min(size_x - 1, x1 + kMargin), y1 = std::min(size_y - 1, y1 + kMargin);

  const double cell = map.getCellLength();
  // Map coordinates are cell corners: integer (x, y) is the lower-left corner of cell (x, y).
  const Eigen::Vector2f corner = map.getWorldCoords(Eigen::Vector2f(static_cast<float>(x0), static_cast<float>(y0)));
  const int width = x1 - x0 + 1;
  const int height = y1 - y0 + 1;
  evaluator::OccupancyGrid grid(width, height, cell, {corner.x(), corner.y(), 0.0});
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      if (!updated(x, y)) continue;
      grid.at(height - 1 - (y - y0), x - x0) = map.getGridProbabilityMap(x + y * size_x);
    }
  }
  return grid;
}

}  // namespace slamsweep::slam::hector
