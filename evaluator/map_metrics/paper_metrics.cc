#include "evaluator/map_metrics/paper_metrics.h"

#include "evaluator/core/input_error.h"
#include "evaluator/map_metrics/scorable_grid.h"
#include "evaluator/map_metrics/usable_cores.h"

#include <future>
#include <string>

namespace slamsweep::evaluator::inline map_metrics {

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

namespace {

/// The metrics before the three scores: options checked, the sizes and the crop window.
PaperMetrics Frame(const OccupancyGrid& grid, const PaperMetricsOptions& options) {
  Validate(options);
  PaperMetrics metrics;
  metrics.options = options;
  metrics.width = grid.width;
  metrics.height = grid.height;
  metrics.window = CellWindow{0, 0, grid.width, grid.height};
  if (options.canvas.crop) metrics.window = KnownCellsWindow(grid, options.canvas.crop_margin_cells);
  return metrics;
}

bool Crops(const PaperMetrics& metrics) { return metrics.window != CellWindow{0, 0, metrics.width, metrics.height}; }

bool TwoCores() { return UsableCores() >= 2; }

// The three metrics only read the grid: with two cores the occupied proportion and the enclosed
// areas run on a helper thread while this one counts the corners.
void Score(const OccupancyGrid& scored, PaperMetrics& metrics) {
  const ScorableGrid scorable = ScorableGrid::Check(scored);  // one check for the three metrics
  const auto occupied_and_enclosed = [&scorable, &metrics] {
    metrics.occupied = ComputeOccupiedProportion(scorable, metrics.options.occupied);
    metrics.enclosed = ComputeEnclosedAreas(scorable, metrics.options.enclosed);
  };
  if (!TwoCores()) {
    occupied_and_enclosed();
    metrics.corners = ComputeCornerCount(scorable, metrics.options.corners);
    return;
  }
  std::future<void> helper = std::async(std::launch::async, occupied_and_enclosed);
  metrics.corners = ComputeCornerCount(scorable, metrics.options.corners);
  helper.get();
}

}  // namespace

PaperMetrics ComputePaperMetrics(const OccupancyGrid& grid, const PaperMetricsOptions& options) {
  PaperMetrics metrics = Frame(grid, options);
  // Copied only when the crop removes something: the metrics' memory budget is a few grids.
  if (Crops(metrics)) {
    Score(CropGrid(grid, metrics.window), metrics);
  } else {
    Score(grid, metrics);
  }
  return metrics;
}

PaperMetrics ComputePaperMetrics(OccupancyGrid&& grid, const PaperMetricsOptions& options) {
  PaperMetrics metrics = Frame(grid, options);
  if (Crops(metrics)) grid = CropGrid(std::move(grid), metrics.window);
  const ScorableGrid scorable = ScorableGrid::Check(grid);
  metrics.occupied = ComputeOccupiedProportion(scorable, metrics.options.occupied);
  // The enclosed areas need only the grid's runs: once they are made, the corner count may use the
  // grid's cells for its structure image (no new full-size image to fault in), while the rest of
  // the enclosed areas runs on a helper thread where there are two cores.
  const LevelRuns levels = BuildLevelRuns(grid);
  const auto enclosed = [&levels, &metrics] {
    metrics.enclosed = ComputeEnclosedAreas(levels, metrics.options.enclosed);
  };
  std::future<void> helper;
  if (TwoCores()) {
    helper = std::async(std::launch::async, enclosed);
  } else {
    enclosed();
  }
  metrics.corners = ComputeCornerCount(scorable, std::move(grid), metrics.options.corners);
  if (helper.valid()) helper.get();
  return metrics;
}

nlohmann::json PaperMetrics::ToJson() const {
  return nlohmann::json{
      {"occupied_to_free_unknown", occupied.occupied_to_free_unknown},
      {"occupied_to_all", occupied.occupied_to_all},
      {"unknown_to_all", occupied.unknown_to_all},
      {"corners", corners.corners},
      {"enclosed_areas", enclosed.enclosed_areas},
      {"width", width},
      {"height", height},
      {"cropped_width", window.width},
      {"cropped_height", window.height},
      {"crop_window", {{"col", window.col}, {"row", window.row}, {"width", window.width}, {"height", window.height}}},
      {"parameters",
       {{"profile", "paper"},
        {"canvas", options.canvas},
        {"occupied", options.occupied},
        {"corners", options.corners},
        {"enclosed", options.enclosed}}},
      {"details", {{"occupied", occupied}, {"corners", corners}, {"enclosed", enclosed}}}};
}

}  // namespace slamsweep::evaluator::inline map_metrics
