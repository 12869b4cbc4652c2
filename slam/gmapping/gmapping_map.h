#pragma once

#include <vector>

#include <gmapping/gridfastslam/gridslamprocessor.h>

#include "evaluator/core/occupancy_grid.h"
#include "slam/gmapping/gmapping_options.h"

namespace slamsweep::slam::gmapping {

/// The map of the best particle, built as GMapping builds its published map: every scan of the
/// particle's trajectory tree registered into a fresh grid at that scan's pose. Cells hold the
/// fraction of beams that ended in them among those that crossed them; never crossed = unknown.
/// `beam_angles` and `laser_pose` are what the processor's scan matcher was given.
evaluator::OccupancyGrid BestParticleMap(const GMapping::GridSlamProcessor& processor, const GmappingOptions& options,
                                         std::vector<double> beam_angles, const GMapping::OrientedPoint& laser_pose);

}  // namespace slamsweep::slam::gmapping
