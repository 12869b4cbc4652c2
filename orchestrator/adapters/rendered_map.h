#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/occupancy_grid.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/occupancy_mapping/occupancy_mapper_options.h"
#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline adapters {

/// A map built from the run's scans placed along a trajectory (evaluator/mapping), for programs
/// that write no map or no stage maps, and for the odometry baseline.
struct RenderedMap {
  evaluator::OccupancyGrid grid;
  /// evaluation.stages stage images (StageImage), evenly spaced over the scans, the last one the final map.
  std::vector<cv::Mat> stages;
  std::size_t scans_used = 0;
  std::size_t scans_outside_trajectory = 0;
};

/// The occupancy mapping of every map rendered from a trajectory (the odometry baseline's, the
/// reference map's): the mapper's defaults at evaluation.map_resolution_m.
evaluator::OccupancyMapperOptions RenderMapperOptions(const EvaluationOptions& evaluation);

/// Places each scan at the trajectory's pose at its stamp and renders the map at
/// evaluation.map_resolution_m, with evaluation.stages stages (none when 0). Throws InputError when
/// no scan falls in the trajectory's time span (naming both ranges) or the map would be too large.
RenderedMap RenderMapFromTrajectory(std::span<const evaluator::LaserScan> scans,
                                    const evaluator::Trajectory& trajectory, const EvaluationOptions& evaluation);

}  // namespace slamsweep::orchestrator::inline adapters
