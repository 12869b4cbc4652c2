#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "evaluator/map_metrics/level_runs.h"

namespace slamsweep::evaluator::inline map_metrics {

/// Counts the enclosed free regions of a whole family of binarisations of one image at once.
///
/// The binarisations are given by ascending thresholds t_0 < t_1 < ... < t_{m-1}: binarisation
/// k frees the known cells whose value is above t_k, and the unknown cells when unknown_free.
/// As k decreases the free set only grows, so one pass frees runs of cells from the brightest
/// down, joins regions with a union-find and reads the count off after each threshold: the
/// cost is that of labelling the image once, whatever the number of thresholds. Cells of one
/// rank (between two consecutive thresholds) are always freed together, so their connected
/// patches are labelled once in the constructor and the passes join patches. Regions are
/// 8-connected; an enclosed region touches no grid border and has at least min_cells cells.
class FreeRegionSweep {
 public:
  /// `thresholds` must be strictly ascending values in [0, 255].
  FreeRegionSweep(const LevelRuns& levels, const std::vector<int>& thresholds);

  /// counts[k]: enclosed regions of binarisation k, for k >= lowest_needed (the pass stops
  /// there; lower entries are 0).
  std::vector<std::int64_t> Count(bool unknown_free, std::int64_t min_cells, int lowest_needed = 0) const;

 private:
  // A patch is an 8-connected set of runs of one rank (the number of thresholds below their
  // values): every binarisation frees it whole, so it is joined once, here, and the passes
  // work on patches, not runs.
  struct Patch {
    std::int32_t id;
    std::int32_t touches_border;
    std::int64_t cells;
  };
  // Two patches of different ranks that touch (8-connected).
  struct Adjacency {
    std::int32_t a;
    std::int32_t b;
  };

  int threshold_count_ = 0;
  std::size_t patch_count_ = 0;
  // Patches and adjacencies grouped by when they become free, flat with offsets (group g is
  // [offsets[g], offsets[g + 1])). Group 0: unknown patches; group g in 1..m: patches of rank
  // m + 1 - g (group m + 1, rank 0, is never free and not stored). An adjacency is in the
  // group of the patch freed later. Within a group, adjacencies that involve no unknown patch
  // come first (up to known_adjacency_ends_[g]), so that a pass with unknown cells occupied
  // stops there instead of testing every adjacency.
  std::vector<Patch> group_patches_;
  std::vector<std::size_t> group_patch_offsets_;
  std::vector<Adjacency> group_adjacencies_;
  std::vector<std::size_t> group_adjacency_offsets_;
  std::vector<std::size_t> known_adjacency_ends_;
};

}  // namespace slamsweep::evaluator::inline map_metrics
