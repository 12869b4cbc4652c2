#pragma once

#include <karto_sdk/Karto.h>

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::slam::slam_toolbox_driver {

/// Karto's occupancy grid of the processed scans at their corrected poses (OccupancyGrid::CreateFromScans,
/// what the node publishes as /map): occupied, free or unknown per cell, as the node's map has them (p = 1, 0 or
/// unknown). A Mapper without a processed scan gives one unknown cell.
evaluator::OccupancyGrid KartoMap(const karto::LocalizedRangeScanVector& scans, double resolution_m);

}  // namespace slamsweep::slam::slam_toolbox_driver
