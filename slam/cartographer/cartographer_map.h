#pragma once

#include <cartographer/mapping/map_builder_interface.h>

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::slam::cartographer_driver {

/// Cartographer's map as one grid at `resolution_m`: every 2D submap's probability grid placed at
/// the submap's global pose (pose graph); where submaps overlap, their known cells are averaged in
/// log-odds. A cell no submap knows is unknown.
evaluator::OccupancyGrid PaintSubmaps(const ::cartographer::mapping::PoseGraphInterface& pose_graph,
                                      double resolution_m);

}  // namespace slamsweep::slam::cartographer_driver
