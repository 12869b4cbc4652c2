#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/occupancy_mapping/grid_extent.h"
#include "evaluator/occupancy_mapping/occupancy_mapper_options.h"
#include "evaluator/occupancy_mapping/scan_beams.h"
#include "evaluator/occupancy_mapping/scan_placement.h"

namespace slamsweep::evaluator::inline occupancy_mapping {

/// The working state of the occupancy mapper: one 16-bit log-odds value per cell (in units of
/// 1/kLogOddsScale, with a flag for "observed") in a flat row-major array, row 0 = top as in OccupancyGrid, so that a
/// 2000 x 2000 map is 8 MB and rays touch little memory. It remembers the box of cells changed
/// since they were last written out, which makes stage maps for an animation cost only the
/// cells that changed.
class LogOddsGrid {
 public:
  /// `options` must be valid (ValidateMapperOptions); `extent` is the area covered.
  LogOddsGrid(const GridExtent& extent, const OccupancyMapperOptions& options);

  /// Traces every usable beam of the scan from the sensor cell along an integer DDA line (the
  /// cells of Bresenham's line):
  /// each cell passed gets a miss, the end cell a hit when the beam marks one. Beams are clipped
  /// to the grid; a beam whose end lies outside marks no hit. Throws InputError (naming
  /// scan_index) for a scan with invalid geometry.
  void Integrate(const PlacedScan& placed, std::size_t scan_index);

  /// A grid of this extent with every cell unknown.
  OccupancyGrid MakeUnknownGrid() const;
  /// Writes p = 1 - 1 / (1 + exp(l)) of every cell changed since the previous call into `grid`
  /// (which must come from MakeUnknownGrid), so that `grid` then equals the full map.
  void WriteChangedCells(OccupancyGrid& grid);

 private:
  void Trace(int col0, int row0, int col1, int row1, bool marks_hit);

  GridExtent extent_;
  double resolution_m_;
  double max_range_m_;
  double no_return_range_m_;
  std::int16_t hit_;
  std::int16_t miss_;
  std::int16_t min_;
  std::int16_t max_;
  std::vector<std::int16_t> log_odds_;
  /// p for every clamped log-odds value, indexed by value - min_.
  std::vector<float> probability_;
  BeamDirections directions_;
  // Changed box, inclusive; empty when min > max.
  int changed_col_min_;
  int changed_col_max_;
  int changed_row_min_;
  int changed_row_max_;
};

}  // namespace slamsweep::evaluator::inline occupancy_mapping
