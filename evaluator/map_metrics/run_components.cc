#include "evaluator/map_metrics/run_components.h"

#include <cassert>
#include <numeric>
#include <utility>

namespace slamsweep::evaluator::inline map_metrics {
namespace {

// Union-find over run indices with path halving; union by index keeps it simple and is fast
// enough because the trees stay shallow for raster-ordered unions.
class DisjointRuns {
 public:
  explicit DisjointRuns(int count) : parent_(static_cast<std::size_t>(count)) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  std::int32_t Find(std::int32_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void Union(std::int32_t a, std::int32_t b) {
    a = Find(a);
    b = Find(b);
    if (a == b) return;
    if (a < b) std::swap(a, b);
    parent_[a] = b;  // the earlier run becomes the root
  }

 private:
  std::vector<std::int32_t> parent_;
};

// Joins every run of `row` with the runs of the row above that it touches, including
// diagonally: [pb, pe) and [cb, ce) are 8-connected unless one ends before the other begins
// with a full cell of gap, i.e. unless pe < cb or ce < pb.
void JoinWithRowAbove(const RowRuns& runs, int row, DisjointRuns& sets) {
  int above = runs.row_first_run(row - 1);
  const int above_end = runs.row_end_run(row - 1);
  int current = runs.row_first_run(row);
  const int current_end = runs.row_end_run(row);
  while (above < above_end && current < current_end) {
    const int pb = runs.begin_col(above), pe = runs.end_col(above);
    const int cb = runs.begin_col(current), ce = runs.end_col(current);
    if (pe < cb) {
      ++above;
    } else if (ce < pb) {
      ++current;
    } else {
      sets.Union(above, current);
      // The run that ends first cannot reach the next run of the other row (runs of one row
      // are separated by at least one cell), so it is done.
      if (pe < ce) {
        ++above;
      } else {
        ++current;
      }
    }
  }
}

DisjointRuns JoinAllRows(const RowRuns& runs) {
  assert(runs.row_end_run(runs.height() - 1) == runs.run_count());
  DisjointRuns sets(runs.run_count());
  for (int row = 1; row < runs.height(); ++row) JoinWithRowAbove(runs, row, sets);
  return sets;
}

bool RunTouchesBorder(const RowRuns& runs, int row, int run) {
  return row == 0 || row == runs.height() - 1 || runs.begin_col(run) == 0 || runs.end_col(run) == runs.width();
}

}  // namespace

void RowRuns::Reset(int width_cells, int height_cells) {
  width_ = width_cells;
  height_ = height_cells;
  row_offsets_.clear();
  row_offsets_.push_back(0);
  row_offsets_.reserve(static_cast<std::size_t>(height_cells) + 1);
  begin_.clear();
  end_.clear();
}

RunComponentLabels LabelRunComponents(const RowRuns& runs) {
  RunComponentLabels labels;
  if (runs.height() == 0) return labels;
  DisjointRuns sets = JoinAllRows(runs);
  labels.component_of_run.assign(static_cast<std::size_t>(runs.run_count()), -1);
  // Roots are the first run of their component, so one raster pass numbers components in
  // order of first appearance.
  for (int row = 0; row < runs.height(); ++row) {
    for (int run = runs.row_first_run(row); run < runs.row_end_run(row); ++run) {
      const std::int32_t root = sets.Find(run);
      std::int32_t& id = labels.component_of_run[root];
      if (id < 0) {
        id = static_cast<std::int32_t>(labels.components.size());
        labels.components.emplace_back();
      }
      labels.component_of_run[run] = id;
      RunComponent& component = labels.components[id];
      component.cells += runs.end_col(run) - runs.begin_col(run);
      component.touches_border = component.touches_border || RunTouchesBorder(runs, row, run);
    }
  }
  return labels;
}

}  // namespace slamsweep::evaluator::inline map_metrics
