#pragma once

#include <opencv2/core/mat.hpp>

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::orchestrator::inline adapters {

/// Grey levels of stage images (orchestrator/DESIGN.md), the map_saver convention.
inline constexpr int kStageOccupied = 0;
inline constexpr int kStageFree = 254;
inline constexpr int kStageUnknown = 205;

/// A stage map as an 8-bit trinary image (row 0 = top), with map_saver's default thresholds as
/// WriteMapServer applies them: v = round(100 p); v >= 65 occupied, v <= 25 free, else unknown.
/// Trinary keeps stage frames comparable whatever grey scale the program used.
cv::Mat StageImage(const evaluator::OccupancyGrid& grid);

}  // namespace slamsweep::orchestrator::inline adapters
