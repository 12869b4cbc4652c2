#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/map_metrics/level_runs.h"
#include "evaluator/map_metrics/scorable_grid.h"

namespace slamsweep::evaluator::inline map_metrics {

/// Paper profile, section III.C. The 8-bit image is value = round(255 * (1 - p)) (free 255,
/// occupied 0); unknown cells take the value u, swept over first_unknown_value,
/// first_unknown_value + unknown_value_step, ... while u < unknown_value_limit.
struct EnclosedAreasOptions {
  /// 0: start from the value of maximum occupancy probability.
  int first_unknown_value = 0;
  int unknown_value_step = 5;
  /// Exclusive upper bound of u.
  int unknown_value_limit = 255;
  /// A free region smaller than this is noise, not a room.
  std::int64_t min_area_cells = 4;
};

/// Throws InputError naming the option when a value is out of range (u values must lie in
/// [0, 255], the step must be positive, the sweep must hold at least one u, the minimum area
/// must be at least 1 cell).
void Validate(const EnclosedAreasOptions& options);

/// One u of the sweep.
struct EnclosedAreasStep {
  int unknown_value = 0;
  /// Otsu's threshold of the image at this u; free cells are strictly above it.
  int otsu_threshold = 0;
  std::int64_t enclosed_areas = 0;
};

struct EnclosedAreas {
  /// The metric: the largest count over the sweep.
  std::int64_t enclosed_areas = 0;
  /// The first u at which that count was reached, and Otsu's threshold there.
  int at_unknown_value = 0;
  int otsu_threshold = 0;
  /// How many different binarisations the sweep produced (each was counted once).
  int distinct_binarisations = 0;
  std::vector<EnclosedAreasStep> sweep;
};

/// Enclosed areas: the 8-connected free regions (cells above Otsu's threshold) that touch no
/// grid border and hold at least min_area_cells cells, maximised over the unknown value u.
/// Throws InputError for bad options or a map that cannot be scored.
EnclosedAreas ComputeEnclosedAreas(const OccupancyGrid& grid, const EnclosedAreasOptions& options = {});
EnclosedAreas ComputeEnclosedAreas(const ScorableGrid& grid, const EnclosedAreasOptions& options = {});
/// The same from the runs of a checked grid (BuildLevelRuns): the grid itself is no longer read.
EnclosedAreas ComputeEnclosedAreas(const LevelRuns& levels, const EnclosedAreasOptions& options = {});

void to_json(nlohmann::json& out, const EnclosedAreasOptions& options);
/// The count with its details, including the whole sweep.
void to_json(nlohmann::json& out, const EnclosedAreas& result);

}  // namespace slamsweep::evaluator::inline map_metrics
