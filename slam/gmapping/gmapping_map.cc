#include "slam/gmapping/gmapping_map.h"

#include <gmapping/scanmatcher/scanmatcher.h>

namespace slamsweep::slam::gmapping {

evaluator::OccupancyGrid BestParticleMap(const GMapping::GridSlamProcessor& processor, const GmappingOptions& options,
                                         std::vector<double> beam_angles, const GMapping::OrientedPoint& laser_pose) {
  const GMapping::GridSlamProcessor::Particle& best = processor.getParticles()[processor.getBestParticleIndex()];
  GMapping::ScanMatcher matcher;
  matcher.setLaserParameters(static_cast<unsigned int>(beam_angles.size()), beam_angles.data(), laser_pose);
  matcher.setlaserMaxRange(options.maxRange);
  matcher.setusableRange(options.maxUrange);
  matcher.setgenerateMap(true);

  // The particle's own map has grown to cover everything it saw: the same extent here.
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
  best.map.getSize(xmin, ymin, xmax, ymax);
  GMapping::ScanMatcherMap map(GMapping::Point((xmin + xmax) / 2, (ymin + ymax) / 2), xmin, ymin, xmax, ymax,
                               options.delta);
  for (const GMapping::GridSlamProcessor::TNode* node = best.node; node != nullptr; node = node->parent) {
    if (node->reading == nullptr) continue;
    const double* ranges = &((*node->reading)[0]);
    matcher.invalidateActiveArea();
    matcher.computeActiveArea(map, node->pose, ranges);
    matcher.registerScan(map, node->pose, ranges);
  }

  const int width = map.getMapSizeX();
  const int height = map.getMapSizeY();
  // map2world gives a cell's centre (world2map rounds): the lower-left corner is half a cell further.
  const GMapping::Point first_cell = map.map2world(0, 0);
  evaluator::OccupancyGrid grid(width, height, options.delta,
                                {first_cell.x - options.delta / 2, first_cell.y - options.delta / 2, 0.0});
  for (int x = 0; x < width; ++x) {
    for (int y = 0; y < height; ++y) {
      const double occupancy = map.cell(x, y);  // PointAccumulator: hits / visits, -1 when never visited
      if (occupancy >= 0.0) grid.at(height - 1 - y, x) = static_cast<float>(occupancy);
    }
  }
  return grid;
}

}  // namespace slamsweep::slam::gmapping
