#include "evaluator/map/free_region_sweep.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <utility>

namespace slamsweep::evaluator {
namespace {

constexpr std::uint16_t kUnknownRank = 0xFFFF;

// Runs of equal rank in raster order, merged from the level runs.
struct RankRuns {
  int width = 0;
  int height = 0;
  std::vector<std::int32_t> row_offsets;
  std::vector<std::int32_t> begin_col;
  std::vector<std::uint16_t> rank;

  int end_col(int run, int row) const { return run + 1 < row_offsets[row + 1] ? begin_col[run + 1] : width; }
};

RankRuns MergeByRank(const LevelRuns& levels, const std::array<std::uint16_t, 256>& rank_of_level) {
  RankRuns runs;
  runs.width = levels.width;
  runs.height = levels.height;
  runs.row_offsets.reserve(static_cast<std::size_t>(levels.height) + 1);
  runs.row_offsets.push_back(0);
  runs.begin_col.reserve(levels.begin_col.size());
  runs.rank.reserve(levels.begin_col.size());
  for (int row = 0; row < levels.height; ++row) {
    int previous = -1;
    for (int run = levels.row_offsets[row]; run < levels.row_offsets[row + 1]; ++run) {
      const std::uint16_t level = levels.level[run];
      const int rank = level == LevelRuns::kUnknownLevel ? kUnknownRank : rank_of_level[level];
      if (rank == previous) continue;  // values of one rank are never separated
      runs.begin_col.push_back(levels.begin_col[run]);
      runs.rank.push_back(static_cast<std::uint16_t>(rank));
      previous = rank;
    }
    runs.row_offsets.push_back(static_cast<std::int32_t>(runs.begin_col.size()));
  }
  return runs;
}

// Calls visit(a, b) once for every pair of 8-connected runs: neighbours in a row, and for each
// run the runs of the row above that hold columns begin - 1 .. end (clipped). The runs of a row
// cover it, so those form one index range, found by a cursor that only moves forward.
template <typename Visit>
void ForEachAdjacentPair(const RankRuns& runs, Visit visit) {
  for (int row = 0; row < runs.height; ++row) {
    const int first = runs.row_offsets[row];
    const int last = runs.row_offsets[row + 1];
    for (int run = first + 1; run < last; ++run) visit(run - 1, run);
    if (row == 0) continue;
    int lo = runs.row_offsets[row - 1];
    for (int run = first; run < last; ++run) {
      const int left = std::max(runs.begin_col[run] - 1, 0);
      const int right = std::min(runs.end_col(run, row), runs.width - 1);
      while (lo + 1 < first && runs.begin_col[lo + 1] <= left) ++lo;
      for (int above = lo; above < first && runs.begin_col[above] <= right; ++above) visit(above, run);
    }
  }
}

}  // namespace

FreeRegionSweep::FreeRegionSweep(const LevelRuns& levels, const std::vector<int>& thresholds)
    : threshold_count_(static_cast<int>(thresholds.size())) {
  // A value's rank is the number of thresholds below it: binarisation k frees rank > k.
  std::array<std::uint16_t, 256> rank_of_level{};
  for (int value = 0; value < 256; ++value) {
    rank_of_level[value] =
        static_cast<std::uint16_t>(std::lower_bound(thresholds.begin(), thresholds.end(), value) - thresholds.begin());
  }
  const RankRuns runs = MergeByRank(levels, rank_of_level);
  const int m = threshold_count_;
  const int never_free = m + 1;
  const auto group_of = [m](std::uint16_t rank) { return rank == kUnknownRank ? 0 : m + 1 - rank; };

  const std::size_t n = runs.begin_col.size();
  cells_.resize(n);
  touches_border_.resize(n);
  group_runs_.assign(static_cast<std::size_t>(m) + 1, {});
  for (int row = 0; row < runs.height; ++row) {
    for (int run = runs.row_offsets[row]; run < runs.row_offsets[row + 1]; ++run) {
      const int end = runs.end_col(run, row);
      cells_[run] = end - runs.begin_col[run];
      touches_border_[run] = (row == 0 || row == runs.height - 1 || runs.begin_col[run] == 0 || end == runs.width);
      const int group = group_of(runs.rank[run]);
      if (group != never_free) group_runs_[group].push_back(run);
    }
  }
  group_adjacencies_.assign(static_cast<std::size_t>(m) + 1, {});
  ForEachAdjacentPair(runs, [&](int a, int b) {
    const int group = std::max(group_of(runs.rank[a]), group_of(runs.rank[b]));
    if (group != never_free) group_adjacencies_[group].push_back({a, b});
  });
}

std::vector<std::int64_t> FreeRegionSweep::Count(bool unknown_free, std::int64_t min_cells, int lowest_needed) const {
  const std::size_t n = cells_.size();
  // Entries are written when their run is freed, before they are read: no need to clear them.
  const auto parent = std::make_unique_for_overwrite<std::int32_t[]>(n);
  const auto cells = std::make_unique_for_overwrite<std::int64_t[]>(n);
  const auto touches = std::make_unique_for_overwrite<std::uint8_t[]>(n);
  // Which runs are free is known from the group alone, but an adjacency to an unknown run
  // that stays occupied must be skipped: mark freed runs.
  const auto freed = std::make_unique<std::uint8_t[]>(n);  // zeroed
  std::int64_t enclosed = 0;

  const auto find = [&parent](std::int32_t x) {
    while (parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  };
  const auto is_enclosed = [&](std::int32_t root) { return touches[root] == 0 && cells[root] >= min_cells ? 1 : 0; };
  const auto free_group = [&](int group) {
    for (const std::int32_t run : group_runs_[static_cast<std::size_t>(group)]) {
      parent[run] = run;
      cells[run] = cells_[run];
      touches[run] = touches_border_[run];
      freed[run] = 1;
      enclosed += is_enclosed(run);
    }
    for (const Adjacency& edge : group_adjacencies_[static_cast<std::size_t>(group)]) {
      if (freed[edge.a] == 0 || freed[edge.b] == 0) continue;
      std::int32_t a = find(edge.a);
      std::int32_t b = find(edge.b);
      if (a == b) continue;
      enclosed -= is_enclosed(a) + is_enclosed(b);
      if (cells[a] < cells[b]) std::swap(a, b);  // the larger region stays the root
      parent[b] = a;
      cells[a] += cells[b];
      touches[a] = static_cast<std::uint8_t>(touches[a] | touches[b]);
      enclosed += is_enclosed(a);
    }
  };

  std::vector<std::int64_t> counts(static_cast<std::size_t>(threshold_count_), 0);
  if (unknown_free) free_group(0);
  for (int k = threshold_count_ - 1; k >= std::max(lowest_needed, 0); --k) {
    // Binarisation k frees rank k + 1 (group m - k) on top of what binarisation k + 1 freed.
    free_group(threshold_count_ - k);
    counts[static_cast<std::size_t>(k)] = enclosed;
  }
  return counts;
}

}  // namespace slamsweep::evaluator
