#pragma once

#include <cstdint>

#include "evaluator/core/occupancy_grid.h"

namespace slamsweep::evaluator::inline map_metrics {

/// An occupancy grid that has been checked once for scoring, so that the map metrics can
/// trust it without scanning it again: its cell vector matches width x height, every known
/// cell holds a probability in [0, 1] and at least one cell is known. It refers to the grid,
/// which must outlive it.
class ScorableGrid {
 public:
  /// Throws InputError when the grid is empty or inconsistent, when a cell is neither unknown
  /// nor a probability in [0, 1] (the message names its row and column), or when no cell is
  /// known ("map has no known cell: nothing to score").
  static ScorableGrid Check(const OccupancyGrid& grid);

  const OccupancyGrid& grid() const { return *grid_; }
  std::int64_t cell_count() const { return static_cast<std::int64_t>(grid_->cells.size()); }
  std::int64_t known_cells() const { return known_cells_; }
  std::int64_t unknown_cells() const { return cell_count() - known_cells_; }
  /// The sum of p over the known cells (in double, from the same pass as the check).
  double known_probability_sum() const { return known_probability_sum_; }

 private:
  ScorableGrid(const OccupancyGrid& grid, std::int64_t known_cells, double known_probability_sum)
      : grid_(&grid), known_cells_(known_cells), known_probability_sum_(known_probability_sum) {}

  const OccupancyGrid* grid_;
  std::int64_t known_cells_;
  double known_probability_sum_;
};

}  // namespace slamsweep::evaluator::inline map_metrics
