#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/map_metrics/canvas_crop.h"
#include "evaluator/map_metrics/corner_count.h"
#include "evaluator/map_metrics/enclosed_areas.h"
#include "evaluator/map_metrics/occupied_proportion.h"

namespace slamsweep::evaluator::inline map_metrics {

/// The canvas rule (spec/metrics.md): a program's canvas is arbitrary, so the metrics are computed
/// on the known cells' bounding box grown by `crop_margin_cells`. `crop = false` is the raw-grid
/// profile (`--no-crop`, `evaluation.crop: false`).
struct CanvasOptions {
  bool crop = true;
  int crop_margin_cells = 2;
};

void to_json(nlohmann::json& out, const CanvasOptions& options);

/// Every parameter of the paper profile (spec/metrics.md, "Map metrics without ground
/// truth"); the defaults are the profile's values.
struct PaperMetricsOptions {
  CanvasOptions canvas;
  OccupiedProportionOptions occupied;
  CornerCountOptions corners;
  EnclosedAreasOptions enclosed;
};

/// Throws InputError naming the first option out of range.
void Validate(const PaperMetricsOptions& options);

/// The three ground-truth-free map metrics of the paper profile, with their details and the
/// options they were computed with (so the numbers carry their specification).
struct PaperMetrics {
  /// The grid as given, and the window the metrics were computed on (the whole grid without crop).
  int width = 0;
  int height = 0;
  CellWindow window;
  OccupiedProportion occupied;
  CornerCount corners;
  EnclosedAreas enclosed;
  PaperMetricsOptions options;

  /// {"occupied_to_free_unknown", "occupied_to_all", "unknown_to_all", "corners",
  ///  "enclosed_areas", "width", "height", "cropped_width", "cropped_height", "crop_window": {col, row,
  ///  width, height}, "parameters": {"profile": "paper", "canvas": {crop, crop_margin_cells},
  ///  "occupied": {...}, "corners": {...}, "enclosed": {...}}, "details": {"occupied": {threshold, cell counts},
  ///  "corners": {...}, "enclosed": {at_unknown_value, otsu_threshold, sweep, ...}}}
  nlohmann::json ToJson() const;
};

/// Higher is worse for all three. With options.canvas.crop the grid is first cropped to
/// KnownCellsWindow (so padding a map with unknown cells changes nothing). Throws InputError for bad options, an empty
/// or inconsistent grid, a cell that is not a probability, or a map with no known cell ("map has no known cell: nothing
/// to score").
PaperMetrics ComputePaperMetrics(const OccupancyGrid& grid, const PaperMetricsOptions& options = {});
/// The same for a grid the caller gives up: it is cropped in place instead of copied, and its cells then hold the
/// corner count's structure image (about a third less peak memory: no second full-size float image).
PaperMetrics ComputePaperMetrics(OccupancyGrid&& grid, const PaperMetricsOptions& options = {});

}  // namespace slamsweep::evaluator::inline map_metrics
