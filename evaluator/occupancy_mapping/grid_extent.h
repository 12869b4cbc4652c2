#pragma once

#include <nlohmann/json.hpp>

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::evaluator::inline occupancy_mapping {

/// The part of the world a map covers: the lower-left corner (yaw 0) and the size in cells.
/// Maps of several runs of one sequence built over the same extent and resolution are
/// comparable cell for cell.
struct GridExtent {
  GridOrigin origin;
  int width_cells = 0;
  int height_cells = 0;

  bool operator==(const GridExtent& other) const {
    return origin.x_m == other.origin.x_m && origin.y_m == other.origin.y_m && origin.yaw_rad == other.origin.yaw_rad &&
           width_cells == other.width_cells && height_cells == other.height_cells;
  }
};

/// The extent of an existing grid (for instance the floor plan a sequence was simulated in).
GridExtent ExtentOf(const OccupancyGrid& grid);

/// Throws InputError (naming `what`) unless the size is positive, the origin finite and its yaw 0.
void ValidateGridExtent(const GridExtent& extent, const char* what);

void to_json(nlohmann::json& out, const GridExtent& extent);

}  // namespace slamsweep::evaluator::inline occupancy_mapping
