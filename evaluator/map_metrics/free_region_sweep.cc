#include "evaluator/map_metrics/free_region_sweep.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <utility>

namespace slamsweep::evaluator::inline map_metrics {
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

struct RunPair {
  std::int32_t a;
  std::int32_t b;
};

// Numbers the patches: 8-connected sets of runs of one rank. A union-find over runs whose
// roots are the first run of their set (unions in raster order keep the trees shallow); ids
// follow the raster order of those first runs. The same walk over adjacent runs collects, in
// `boundaries`, the pairs of different ranks that may both become free (rank 0 never does),
// so that the image is walked once.
std::vector<std::int32_t> LabelPatches(const RankRuns& runs, std::vector<RunPair>& boundaries) {
  const std::size_t n = runs.begin_col.size();
  std::vector<std::int32_t> parent(n);
  for (std::size_t i = 0; i < n; ++i) parent[i] = static_cast<std::int32_t>(i);
  const auto find = [&parent](std::int32_t x) {
    while (parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  };
  // A run has at most about 5 adjacent pairs, and on noisy real maps fewer than 3 of them
  // join different ranks; reserving 3 per run means the vector rarely moves (push_back stays
  // correct when it must). Reserving more did not pay: a larger block pushed the whole
  // metric's heap past malloc's trim threshold, and every call then faulted its pages in anew.
  boundaries.clear();
  boundaries.reserve(3 * n);
  ForEachAdjacentPair(runs, [&](int a, int b) {
    const std::uint16_t rank_a = runs.rank[static_cast<std::size_t>(a)];
    const std::uint16_t rank_b = runs.rank[static_cast<std::size_t>(b)];
    if (rank_a != rank_b) {
      if (rank_a != 0 && rank_b != 0) boundaries.push_back({a, b});
      return;
    }
    const std::int32_t root_a = find(a);
    const std::int32_t root_b = find(b);
    if (root_a < root_b) parent[root_b] = root_a;
    if (root_b < root_a) parent[root_a] = root_b;
  });
  // Parents only ever point to earlier runs, so one forward pass turns parents into ids
  // (stored as -id - 1 while the pass runs, to tell them from parents).
  std::int32_t next_id = 0;
  for (std::size_t i = 0; i < n; ++i) {
    parent[i] = parent[i] == static_cast<std::int32_t>(i) ? -(next_id++) - 1 : parent[parent[i]];
  }
  for (std::int32_t& id : parent) id = -id - 1;
  return parent;
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
  std::vector<RunPair> boundaries;  // then reused for the patch pairs
  const std::vector<std::int32_t> patch_of_run = LabelPatches(runs, boundaries);
  patch_count_ = 0;
  for (const std::int32_t patch : patch_of_run)
    patch_count_ = std::max(patch_count_, static_cast<std::size_t>(patch) + 1);

  const int m = threshold_count_;
  const std::size_t groups = static_cast<std::size_t>(m) + 1;  // stored groups 0..m
  const std::size_t never_free = groups;
  const auto group_of_rank = [m](std::uint16_t rank) -> std::size_t {
    return rank == kUnknownRank ? 0 : static_cast<std::size_t>(m + 1 - rank);
  };

  // Patches, gathered from their runs in id order (ids follow raster order of first runs).
  std::vector<Patch> patches(patch_count_, Patch{0, 0, 0});
  std::vector<std::uint16_t> patch_rank(patch_count_, 0);
  for (int row = 0; row < runs.height; ++row) {
    for (int run = runs.row_offsets[row]; run < runs.row_offsets[row + 1]; ++run) {
      Patch& patch = patches[static_cast<std::size_t>(patch_of_run[run])];
      const int end = runs.end_col(run, row);
      patch.id = patch_of_run[run];
      patch.cells += end - runs.begin_col[run];
      patch.touches_border |= (row == 0 || row == runs.height - 1 || runs.begin_col[run] == 0 || end == runs.width);
      patch_rank[static_cast<std::size_t>(patch.id)] = runs.rank[run];
    }
  }

  // Both lists are bucketed with a counting sort (count, then place), so that no vector grows
  // while it is filled.
  group_patch_offsets_.assign(groups + 1, 0);
  for (const std::uint16_t rank : patch_rank) {
    const std::size_t group = group_of_rank(rank);
    if (group != never_free) ++group_patch_offsets_[group + 1];
  }
  for (std::size_t g = 0; g < groups; ++g) group_patch_offsets_[g + 1] += group_patch_offsets_[g];
  group_patches_.resize(group_patch_offsets_[groups]);
  {
    std::vector<std::size_t> next(group_patch_offsets_.begin(), group_patch_offsets_.end() - 1);
    for (std::size_t p = 0; p < patch_count_; ++p) {
      const std::size_t group = group_of_rank(patch_rank[p]);
      if (group != never_free) group_patches_[next[group]++] = patches[p];
    }
  }

  // Each patch's group, looked up once per pair below.
  std::vector<std::uint16_t> patch_group(patch_count_);
  for (std::size_t p = 0; p < patch_count_; ++p)
    patch_group[p] = static_cast<std::uint16_t>(group_of_rank(patch_rank[p]));
  // Adjacency buckets: 2 g for those of group g between known patches, 2 g + 1 for those with
  // an unknown patch.
  const auto bucket_of = [&](const Adjacency& pair) -> std::size_t {
    const std::size_t group_a = patch_group[static_cast<std::size_t>(pair.a)];
    const std::size_t group_b = patch_group[static_cast<std::size_t>(pair.b)];
    return 2 * std::max(group_a, group_b) + static_cast<std::size_t>(std::min(group_a, group_b) == 0);
  };
  // Along a boundary the same two patches touch on row after row. A patch usually alternates
  // between a few neighbours (left and right walls), so remembering each patch's latest
  // partner in both directions drops most repeats; the rest are harmless to the union-find.
  // The unique pairs are compacted in place and counted per bucket, then placed.
  std::vector<std::size_t> bucket_offsets(2 * groups + 1, 0);
  std::vector<std::uint16_t> bucket_of_unique(boundaries.size());  // placing then reads it in order
  std::size_t unique = 0;
  {
    std::vector<std::int32_t> latest_partner(patch_count_, -1);
    for (const RunPair& runs_pair : boundaries) {
      const Adjacency pair{patch_of_run[runs_pair.a], patch_of_run[runs_pair.b]};
      if (latest_partner[pair.a] == pair.b || latest_partner[pair.b] == pair.a) continue;
      latest_partner[pair.a] = pair.b;
      latest_partner[pair.b] = pair.a;
      const std::size_t bucket = bucket_of(pair);
      bucket_of_unique[unique] = static_cast<std::uint16_t>(bucket);
      boundaries[unique++] = {pair.a, pair.b};
      ++bucket_offsets[bucket + 1];
    }
  }
  for (std::size_t k = 0; k + 1 < bucket_offsets.size(); ++k) bucket_offsets[k + 1] += bucket_offsets[k];
  group_adjacencies_.resize(unique);
  {
    std::vector<std::size_t> next(bucket_offsets.begin(), bucket_offsets.end() - 1);
    for (std::size_t i = 0; i < unique; ++i) {
      group_adjacencies_[next[bucket_of_unique[i]]++] = {boundaries[i].a, boundaries[i].b};
    }
  }
  group_adjacency_offsets_.resize(groups + 1);
  known_adjacency_ends_.resize(groups);
  for (std::size_t g = 0; g <= groups; ++g) group_adjacency_offsets_[g] = bucket_offsets[2 * g];
  for (std::size_t g = 0; g < groups; ++g) known_adjacency_ends_[g] = bucket_offsets[2 * g + 1];
}

std::vector<std::int64_t> FreeRegionSweep::Count(bool unknown_free, std::int64_t min_cells, int lowest_needed) const {
  // One record per patch, so that a find or a union touches one cache line per patch instead
  // of one per array. Entries are written when their patch is freed, before they are read:
  // no need to clear them.
  struct Node {
    std::int32_t parent;
    std::int32_t touches_border;
    std::int64_t cells;
  };
  const auto nodes = std::make_unique_for_overwrite<Node[]>(patch_count_);
  std::int64_t enclosed = 0;

  const auto find = [&nodes](std::int32_t x) {
    while (nodes[x].parent != x) {
      nodes[x].parent = nodes[nodes[x].parent].parent;
      x = nodes[x].parent;
    }
    return x;
  };
  const auto is_enclosed = [&](const Node& root) {
    return root.touches_border == 0 && root.cells >= min_cells ? 1 : 0;
  };
  const auto free_group = [&](std::size_t group) {
    for (std::size_t i = group_patch_offsets_[group]; i < group_patch_offsets_[group + 1]; ++i) {
      const Patch& freed = group_patches_[i];
      Node& node = nodes[freed.id];
      node = {freed.id, freed.touches_border, freed.cells};
      enclosed += is_enclosed(node);
    }
    // With unknown cells occupied, adjacencies to unknown patches (stored last) join nothing.
    const std::size_t end = unknown_free ? group_adjacency_offsets_[group + 1] : known_adjacency_ends_[group];
    for (std::size_t i = group_adjacency_offsets_[group]; i < end; ++i) {
      std::int32_t a = find(group_adjacencies_[i].a);
      std::int32_t b = find(group_adjacencies_[i].b);
      if (a == b) continue;
      enclosed -= is_enclosed(nodes[a]) + is_enclosed(nodes[b]);
      if (nodes[a].cells < nodes[b].cells) std::swap(a, b);  // the larger region stays the root
      nodes[b].parent = a;
      nodes[a].cells += nodes[b].cells;
      nodes[a].touches_border |= nodes[b].touches_border;
      enclosed += is_enclosed(nodes[a]);
    }
  };

  std::vector<std::int64_t> counts(static_cast<std::size_t>(threshold_count_), 0);
  if (unknown_free) free_group(0);
  for (int k = threshold_count_ - 1; k >= std::max(lowest_needed, 0); --k) {
    // Binarisation k frees rank k + 1 (group m - k) on top of what binarisation k + 1 freed.
    free_group(static_cast<std::size_t>(threshold_count_ - k));
    counts[static_cast<std::size_t>(k)] = enclosed;
  }
  return counts;
}

}  // namespace slamsweep::evaluator::inline map_metrics
