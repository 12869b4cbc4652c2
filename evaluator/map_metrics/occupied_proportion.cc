#include "evaluator/map_metrics/occupied_proportion.h"

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline map_metrics {

void Validate(const OccupiedProportionOptions& options) {
  if (!(options.unknown_occupancy >= 0.0 && options.unknown_occupancy <= 1.0)) {
    throw InputError("option occupied.unknown_occupancy = " + std::to_string(options.unknown_occupancy) +
                     ": expected a probability in [0, 1]");
  }
}

OccupiedProportion ComputeOccupiedProportion(const OccupancyGrid& grid, const OccupiedProportionOptions& options) {
  Validate(options);
  return ComputeOccupiedProportion(ScorableGrid::Check(grid), options);
}

OccupiedProportion ComputeOccupiedProportion(const ScorableGrid& scorable, const OccupiedProportionOptions& options) {
  Validate(options);
  const OccupancyGrid& grid = scorable.grid();
  const double unknown_p = options.unknown_occupancy;

  // The threshold needs the sum of p, which the grid's check computed; one pass classifies.
  const std::size_t n = grid.cells.size();
  const float* cells = grid.cells.data();
  const double sum_known = scorable.known_probability_sum();
  const double sum_p = sum_known + unknown_p * static_cast<double>(scorable.unknown_cells());

  OccupiedProportion result;
  result.total_cells = scorable.cell_count();
  result.unknown_cells = scorable.unknown_cells();
  result.threshold = sum_p / static_cast<double>(result.total_cells);

  // For a float p, (double)p > t exactly when p > the largest float not above t, so the
  // comparison can stay in float (and vectorise). Unknown cells are negative and the
  // threshold is not, so they never pass it.
  float float_threshold = static_cast<float>(result.threshold);
  if (static_cast<double>(float_threshold) > result.threshold) {
    float_threshold = std::nextafter(float_threshold, -std::numeric_limits<float>::infinity());
  }
  std::int64_t occupied_known = 0;
  for (std::size_t j = 0; j < n; ++j) occupied_known += static_cast<int>(cells[j] > float_threshold);
  // Unknown cells all share one p, so they are occupied together or not at all.
  const bool unknown_occupied = unknown_p > result.threshold;
  result.occupied_cells = occupied_known + (unknown_occupied ? result.unknown_cells : 0);
  result.free_cells = scorable.known_cells() - occupied_known;

  const double total = static_cast<double>(result.total_cells);
  const std::int64_t not_occupied = result.total_cells - result.occupied_cells;
  // A map where every cell is above the mean is impossible (the mean is not below every
  // value), so not_occupied > 0; the guard only keeps the division well defined.
  result.occupied_to_free_unknown =
      not_occupied > 0 ? static_cast<double>(result.occupied_cells) / static_cast<double>(not_occupied) : 0.0;
  result.occupied_to_all = static_cast<double>(result.occupied_cells) / total;
  result.unknown_to_all = static_cast<double>(result.unknown_cells) / total;
  return result;
}

void to_json(nlohmann::json& out, const OccupiedProportionOptions& options) {
  out = nlohmann::json{{"unknown_occupancy", options.unknown_occupancy}};
}

void to_json(nlohmann::json& out, const OccupiedProportion& result) {
  out = nlohmann::json{{"occupied_to_free_unknown", result.occupied_to_free_unknown},
                       {"occupied_to_all", result.occupied_to_all},
                       {"unknown_to_all", result.unknown_to_all},
                       {"threshold", result.threshold},
                       {"occupied_cells", result.occupied_cells},
                       {"free_cells", result.free_cells},
                       {"unknown_cells", result.unknown_cells},
                       {"total_cells", result.total_cells}};
}

}  // namespace slamsweep::evaluator::inline map_metrics
