#pragma once

#include <cstdint>
#include <vector>

namespace slamsweep::evaluator::inline map_metrics {

/// The foreground cells of a binary image stored as horizontal runs, row by row (compressed
/// sparse rows). Maps are mostly long stretches of one value, so runs are far fewer than
/// cells, and labelling runs is much cheaper than labelling cells.
class RowRuns {
 public:
  RowRuns() = default;
  RowRuns(int width_cells, int height_cells) { Reset(width_cells, height_cells); }

  /// Forgets all runs and starts again at row 0; keeps the allocated memory.
  void Reset(int width_cells, int height_cells);
  /// Appends a run of cells [begin_col, end_col) to the current row. Runs of one row must come
  /// left to right and must not touch (begin_col > end_col of the previous run).
  void Add(int begin_col, int end_col) {
    begin_.push_back(begin_col);
    end_.push_back(end_col);
  }
  /// Closes the current row; call it once per row, `height` times in all.
  void EndRow() { row_offsets_.push_back(static_cast<std::int32_t>(begin_.size())); }

  int width() const { return width_; }
  int height() const { return height_; }
  int run_count() const { return static_cast<int>(begin_.size()); }
  int row_first_run(int row) const { return row_offsets_[row]; }
  int row_end_run(int row) const { return row_offsets_[row + 1]; }
  int begin_col(int run) const { return begin_[run]; }
  int end_col(int run) const { return end_[run]; }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<std::int32_t> row_offsets_{0};
  std::vector<std::int32_t> begin_;
  std::vector<std::int32_t> end_;
};

/// One 8-connected component of the foreground.
struct RunComponent {
  std::int64_t cells = 0;
  /// True when a cell of the component lies in the first or last row or column.
  bool touches_border = false;
};

struct RunComponentLabels {
  /// Index into `components` for every run.
  std::vector<std::int32_t> component_of_run;
  std::vector<RunComponent> components;
};

/// The 8-connected components of the runs (two cells are connected when they share an edge or
/// a corner), the connectivity of OpenCV's connectedComponents(..., 8) and of the regions whose
/// outer borders Suzuki-Abe border following traces. The runs must be complete: `height` rows.
RunComponentLabels LabelRunComponents(const RowRuns& runs);

}  // namespace slamsweep::evaluator::inline map_metrics
