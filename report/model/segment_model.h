#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "report/model/box_summary.h"
#include "report/model/mean_std.h"
#include "report/model/sweep_model.h"

namespace slamsweep::report::inline model {

/// One row of a table at one segment length.
struct SegmentCell {
  /// Every segment of every successful run of the row, pooled (runs/<id>/rpe_segments.csv): the boxes.
  std::optional<BoxSummary> translation_m;
  std::optional<BoxSummary> translation_pct;
  std::optional<BoxSummary> rotation_deg_per_m;
  /// Over the runs scored at this length: each run's mean drift (%) and mean rotation drift (deg/m)
  /// (result.json's metric_details.segment_rpe), mean +- sample std.
  MeanStd mean_drift_pct;
  MeanStd mean_rotation_deg_per_m;
  /// The lowest mean drift at this length among the table's rows whose odometry is not the reference.
  bool best = false;
};

struct SegmentRow {
  std::size_t row = 0;             ///< index into SequenceModel::rows
  std::vector<SegmentCell> cells;  ///< parallel to SegmentTable::lengths_m
  /// What a reader must know before comparing this row (runs scored at other lengths, unreadable files).
  std::vector<std::string> notes;
};

/// The segment RPE of one table (sequence x noise): drift at each segment length, per row.
struct SegmentTable {
  std::string table_key;
  /// Every length some run of the table was scored at, ascending. Runs of one sequence get the same
  /// lengths (they come from its reference path or the sweep's evaluation.rpe_segments_m).
  std::vector<double> lengths_m;
  /// How the lengths were chosen: "10, 20, 30, 40 and 50 % of the reference path (123.4 m), rounded to
  /// 1 m" or "as configured (evaluation.rpe_segments_m)".
  std::string lengths_from;
  std::vector<SegmentRow> rows;  ///< rows with a successful run scored by segment RPE, in table order
  std::vector<std::string> notes;
};

/// The segment table of `sequence`, or nullopt when none of its successful runs has a segment RPE
/// (no reference, or a sweep made before it existed). Never throws for bad run files: what cannot be
/// read is left out and named in a note.
std::optional<SegmentTable> BuildSegmentTable(const SweepModel& model, const SequenceModel& sequence);

}  // namespace slamsweep::report::inline model
