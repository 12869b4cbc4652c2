#include "evaluator/occupancy_mapping/grid_extent.h"

#include <cmath>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline occupancy_mapping {

GridExtent ExtentOf(const OccupancyGrid& grid) {
  GridExtent extent;
  extent.origin = grid.origin;
  extent.width_cells = grid.width;
  extent.height_cells = grid.height;
  return extent;
}

void ValidateGridExtent(const GridExtent& extent, const char* what) {
  if (extent.width_cells <= 0 || extent.height_cells <= 0) {
    throw InputError(std::string(what) + ": size must be positive, got " + std::to_string(extent.width_cells) + " x " +
                     std::to_string(extent.height_cells) + " cells");
  }
  if (!std::isfinite(extent.origin.x_m) || !std::isfinite(extent.origin.y_m)) {
    throw InputError(std::string(what) + ": origin must be finite");
  }
  if (extent.origin.yaw_rad != 0.0) {
    throw InputError(std::string(what) + ": origin yaw must be 0 (rotated maps are not supported), got " +
                     std::to_string(extent.origin.yaw_rad) + " rad");
  }
}

void to_json(nlohmann::json& out, const GridExtent& extent) {
  out = nlohmann::json{{"origin_x_m", extent.origin.x_m},
                       {"origin_y_m", extent.origin.y_m},
                       {"width_cells", extent.width_cells},
                       {"height_cells", extent.height_cells}};
}

}  // namespace slamsweep::evaluator::inline occupancy_mapping
