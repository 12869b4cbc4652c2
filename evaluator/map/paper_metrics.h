#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/map/corner_count.h"
#include "evaluator/map/enclosed_areas.h"
#include "evaluator/map/occupied_proportion.h"

namespace slamsweep::evaluator {

/// Every parameter of the paper profile (spec/metrics.md, "Map metrics without ground
/// truth"); the defaults are the profile's values.
struct PaperMetricsOptions {
  OccupiedProportionOptions occupied;
  CornerCountOptions corners;
  EnclosedAreasOptions enclosed;
};

/// Throws InputError naming the first option out of range.
void Validate(const PaperMetricsOptions& options);

/// The three ground-truth-free map metrics of the paper profile, with their details and the
/// options they were computed with (so the numbers carry their specification).
struct PaperMetrics {
  OccupiedProportion occupied;
  CornerCount corners;
  EnclosedAreas enclosed;
  PaperMetricsOptions options;

  /// {"occupied_to_free_unknown", "occupied_to_all", "unknown_to_all", "corners",
  ///  "enclosed_areas", "parameters": {"profile": "paper", "occupied": {...}, "corners": {...},
  ///  "enclosed": {...}}, "details": {"occupied": {threshold, cell counts},
  ///  "corners": {...}, "enclosed": {at_unknown_value, otsu_threshold, sweep, ...}}}
  nlohmann::json ToJson() const;
};

/// Higher is worse for all three. Throws InputError for bad options, an empty or inconsistent
/// grid, a cell that is not a probability, or a map with no known cell ("map has no known
/// cell: nothing to score").
PaperMetrics ComputePaperMetrics(const OccupancyGrid& grid, const PaperMetricsOptions& options = {});

}  // namespace slamsweep::evaluator
