#include "evaluator/map/paper_metrics.h"

#include "evaluator/core/input_error.h"
#include "evaluator/map/scorable_grid.h"

#include <string>

namespace slamsweep::evaluator {

void to_json(nlohmann::json& out, const CanvasOptions& options) {
  out = nlohmann::json{{"crop", options.crop}, {"crop_margin_cells", options.crop_margin_cells}};
}

void Validate(const PaperMetricsOptions& options) {
  if (options.canvas.crop_margin_cells < 0) {
    throw InputError("crop_margin_cells: expected 0 or more cells, got " +
                     std::to_string(options.canvas.crop_margin_cells));
  }
  Validate(options.occupied);
  Validate(options.corners);
  Validate(options.enclosed);
}

PaperMetrics ComputePaperMetrics(const OccupancyGrid& grid, const PaperMetricsOptions& options) {
  Validate(options);
  PaperMetrics metrics;
  metrics.options = options;
  metrics.width = grid.width;
  metrics.height = grid.height;
  metrics.window = CellWindow{0, 0, grid.width, grid.height};
  if (options.canvas.crop) metrics.window = KnownCellsWindow(grid, options.canvas.crop_margin_cells);
  // Copied only when the crop removes something: the metrics' memory budget is a few grids.
  const bool cropped = metrics.window != CellWindow{0, 0, grid.width, grid.height};
  const OccupancyGrid cropped_grid = cropped ? CropGrid(grid, metrics.window) : OccupancyGrid();
  const ScorableGrid scorable = ScorableGrid::Check(cropped ? cropped_grid : grid);  // one check for the three metrics
  metrics.occupied = ComputeOccupiedProportion(scorable, options.occupied);
  metrics.corners = ComputeCornerCount(scorable, options.corners);
  metrics.enclosed = ComputeEnclosedAreas(scorable, options.enclosed);
  return metrics;
}

nlohmann::json PaperMetrics::ToJson() const {
  return nlohmann::json{{"occupied_to_free_unknown", occupied.occupied_to_free_unknown},
                        {"occupied_to_all", occupied.occupied_to_all},
                        {"unknown_to_all", occupied.unknown_to_all},
                        {"corners", corners.corners},
                        {"enclosed_areas", enclosed.enclosed_areas},
                        {"width", width},
                        {"height", height},
                        {"cropped_width", window.width},
                        {"cropped_height", window.height},
                        {"crop_window",
                         {{"col", window.col}, {"row", window.row}, {"width", window.width}, {"height", window.height}}},
                        {"parameters",
                         {{"profile", "paper"},
                          {"canvas", options.canvas},
                          {"occupied", options.occupied},
                          {"corners", options.corners},
                          {"enclosed", options.enclosed}}},
                        {"details", {{"occupied", occupied}, {"corners", corners}, {"enclosed", enclosed}}}};
}

}  // namespace slamsweep::evaluator
