#pragma once

#include <cstdint>
#include <vector>

#include "evaluator/map/level_runs.h"

namespace slamsweep::evaluator {

/// Counts the enclosed free regions of a whole family of binarisations of one image at once.
///
/// The binarisations are given by ascending thresholds t_0 < t_1 < ... < t_{m-1}: binarisation
/// k frees the known cells whose value is above t_k, and the unknown cells when unknown_free.
/// As k decreases the free set only grows, so one pass frees runs of cells from the brightest
/// down, joins regions with a union-find and reads the count off after each threshold: the
/// cost is that of labelling the image once, whatever the number of thresholds. Regions are
/// 8-connected; an enclosed region touches no grid border and has at least min_cells cells.
class FreeRegionSweep {
 public:
  /// `thresholds` must be strictly ascending values in [0, 255].
  FreeRegionSweep(const LevelRuns& levels, const std::vector<int>& thresholds);

  /// counts[k]: enclosed regions of binarisation k, for k >= lowest_needed (the pass stops
  /// there; lower entries are 0).
  std::vector<std::int64_t> Count(bool unknown_free, std::int64_t min_cells, int lowest_needed = 0) const;

 private:
  struct Adjacency {
    std::int32_t a;
    std::int32_t b;
  };

  int threshold_count_ = 0;
  // Runs of cells of equal rank (the number of thresholds below their value), raster order.
  std::vector<std::int32_t> cells_;
  std::vector<std::uint8_t> touches_border_;
  // Runs and adjacencies grouped by when they become free. Group 0: unknown runs; group g in
  // 1..m: runs of rank m + 1 - g (group m + 1, rank 0, is never free and not stored). An
  // adjacency joins two runs and is in the group of the one freed later. Raster order within
  // a group keeps the pass streaming through memory.
  std::vector<std::vector<std::int32_t>> group_runs_;
  std::vector<std::vector<Adjacency>> group_adjacencies_;
};

}  // namespace slamsweep::evaluator
