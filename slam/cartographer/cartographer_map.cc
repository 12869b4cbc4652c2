#include "slam/cartographer/cartographer_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <cartographer/mapping/2d/probability_grid.h>
#include <cartographer/mapping/2d/submap_2d.h>

namespace slamsweep::slam::cartographer_driver {
namespace {

namespace carto = ::cartographer;

struct PlacedSubmap {
  const carto::mapping::ProbabilityGrid* grid;
  /// From the submap grid's frame (the trajectory's local frame) to the global frame.
  carto::transform::Rigid2d local_to_global;
};

}  // namespace

evaluator::OccupancyGrid PaintSubmaps(const carto::mapping::PoseGraphInterface& pose_graph, double resolution_m) {
  std::vector<PlacedSubmap> submaps;
  double min_x = std::numeric_limits<double>::max(), min_y = min_x;
  double max_x = std::numeric_limits<double>::lowest(), max_y = max_x;
  for (const auto& entry : pose_graph.GetAllSubmapData()) {
    const auto* submap = dynamic_cast<const carto::mapping::Submap2D*>(entry.data.submap.get());
    if (submap == nullptr) continue;
    const auto* grid = dynamic_cast<const carto::mapping::ProbabilityGrid*>(submap->grid());
    if (grid == nullptr) continue;
    const carto::transform::Rigid2d local_to_global =
        carto::transform::Project2D(entry.data.pose * submap->local_pose().inverse());
    submaps.push_back({grid, local_to_global});
    const carto::mapping::MapLimits& limits = grid->limits();
    const double width = limits.cell_limits().num_x_cells * limits.resolution();
    const double height = limits.cell_limits().num_y_cells * limits.resolution();
    for (const Eigen::Vector2d& corner : {Eigen::Vector2d(limits.max().x(), limits.max().y()),
                                          Eigen::Vector2d(limits.max().x() - width, limits.max().y()),
                                          Eigen::Vector2d(limits.max().x(), limits.max().y() - height),
                                          Eigen::Vector2d(limits.max().x() - width, limits.max().y() - height)}) {
      const Eigen::Vector2d global = local_to_global * corner;
      min_x = std::min(min_x, global.x()), max_x = std::max(max_x, global.x());
      min_y = std::min(min_y, global.y()), max_y = std::max(max_y, global.y());
    }
  }
  if (submaps.empty()) return evaluator::OccupancyGrid(1, 1, resolution_m);

  const int width = static_cast<int>(std::ceil((max_x - min_x) / resolution_m));
  const int height = static_cast<int>(std::ceil((max_y - min_y) / resolution_m));
  std::vector<float> log_odds(static_cast<std::size_t>(width) * height, 0.0f);
  std::vector<std::uint16_t> known(log_odds.size(), 0);
  for (const PlacedSubmap& placed : submaps) {
    const carto::transform::Rigid2d global_to_local = placed.local_to_global.inverse();
    for (int row = 0; row < height; ++row) {
      const double y = min_y + (height - 1 - row + 0.5) * resolution_m;
      for (int col = 0; col < width; ++col) {
        const double x = min_x + (col + 0.5) * resolution_m;
        const Eigen::Vector2d local = global_to_local * Eigen::Vector2d(x, y);
        const Eigen::Array2i cell = placed.grid->limits().GetCellIndex(local.cast<float>());
        if (!placed.grid->limits().Contains(cell) || !placed.grid->IsKnown(cell)) continue;
        const float p = std::clamp(placed.grid->GetProbability(cell), 0.01f, 0.99f);
        const std::size_t index = static_cast<std::size_t>(row) * width + col;
        log_odds[index] += std::log(p / (1.0f - p));
        ++known[index];
      }
    }
  }
  evaluator::OccupancyGrid map(width, height, resolution_m, {min_x, min_y, 0.0});
  for (std::size_t i = 0; i < log_odds.size(); ++i) {
    if (known[i] == 0) continue;
    const float mean = log_odds[i] / known[i];
    map.cells[i] = 1.0f / (1.0f + std::exp(-mean));
  }
  return map;
}

}  // namespace slamsweep::slam::cartographer_driver
