#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/map_metrics/scorable_grid.h"

namespace slamsweep::evaluator::inline map_metrics {

/// Paper profile, section III.A. The threshold itself has no parameter: it is the mean p.
struct OccupiedProportionOptions {
  /// Occupancy probability given to unknown cells, both in the mean and in the comparison.
  /// The paper draws unknown space white, like free space, hence 0.
  double unknown_occupancy = 0.0;
};

/// Throws InputError naming the option when unknown_occupancy is not in [0, 1].
void Validate(const OccupiedProportionOptions& options);

struct OccupiedProportion {
  /// occupied / (free + unknown), i.e. occupied / (all - occupied): the quantity of the
  /// paper's Fig. 5, the headline value.
  double occupied_to_free_unknown = 0.0;
  double occupied_to_all = 0.0;
  double unknown_to_all = 0.0;
  /// Mean p over all cells; a cell is occupied when its p is strictly above it.
  double threshold = 0.0;
  std::int64_t occupied_cells = 0;
  /// Known cells that are not occupied.
  std::int64_t free_cells = 0;
  std::int64_t unknown_cells = 0;
  std::int64_t total_cells = 0;
};

/// Occupied proportion of a map. Throws InputError for bad options or a map that cannot be
/// scored (see ScorableGrid::Check).
OccupiedProportion ComputeOccupiedProportion(const OccupancyGrid& grid, const OccupiedProportionOptions& options = {});
OccupiedProportion ComputeOccupiedProportion(const ScorableGrid& grid, const OccupiedProportionOptions& options = {});

void to_json(nlohmann::json& out, const OccupiedProportionOptions& options);
/// The details (threshold and cell counts) next to the three ratios.
void to_json(nlohmann::json& out, const OccupiedProportion& result);

}  // namespace slamsweep::evaluator::inline map_metrics
