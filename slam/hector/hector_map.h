#pragma once

#include <iostream>  // hector_slam_lib uses std::cout without including it

#include <slam_main/HectorSlamProcessor.h>

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::slam::hector {

/// The finest level of Hector's map, cut to the cells it has updated (plus a 2-cell margin): a cell
/// never updated has log-odds exactly 0 and is unknown; others hold p = odds / (1 + odds).
evaluator::OccupancyGrid FinestMap(const hectorslam::HectorSlamProcessor& processor);

}  // namespace slamsweep::slam::hector
