#pragma once

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/map_compare/map_compare.h"

namespace slamsweep::evaluator::inline map_compare {

/// `grid` with every cell reduced to the class map comparison sees: occupied (p = 1), free (p = 0)
/// or unknown, by the thresholds of `options`. Such a grid survives a trinary map file exactly.
OccupancyGrid ClassifyCells(const OccupancyGrid& grid, const MapCompareOptions& options = {});

/// `grid` on a lattice of `resolution_m` cells with the same lower-left corner, for comparing a
/// map with a reference of another cell size. Classes are kept, not probabilities: each new cell
/// gathers the old cells whose centres fall inside it (or, when none does, the old cell under
/// its own centre) and becomes occupied (p = 1) if any of them is occupied, else free (p = 0) if
/// any is free, else unknown, with the thresholds of `options`. So a one-cell wall survives a
/// coarser lattice and unknown padding never turns into free space. The same resolution (within
/// 1e-9 relative) returns the grid unchanged. Throws InputError for resolution_m <= 0.
OccupancyGrid ResampleToResolution(const OccupancyGrid& grid, double resolution_m,
                                   const MapCompareOptions& options = {});

/// The same lattice change keeping occupancy probabilities (grey levels), for the paper's map
/// metrics, which read the grey image: a finer lattice copies the old cell under each new cell's
/// centre (a 0.1 m map on 0.05 m cells is each cell repeated 2 x 2); a coarser one gives each new
/// cell the highest probability among the known old cells whose centres fall inside it (unknown
/// when none is known), so a one-cell wall survives as it does in ResampleToResolution. The same
/// resolution (within 1e-9 relative) returns the grid unchanged. Throws InputError for resolution_m <= 0.
OccupancyGrid ResampleKeepingProbabilities(const OccupancyGrid& grid, double resolution_m);

}  // namespace slamsweep::evaluator::inline map_compare
