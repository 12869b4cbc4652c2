#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "report/model/mean_std.h"
#include "report/model/run_record.h"

namespace slamsweep::report {

/// One table column: one flat metric computed under one specification. Runs whose
/// specifications differ (say alignment se2 and sim2) get separate columns, because numbers from
/// different specifications must never share a column (spec/metrics.md).
struct MetricColumn {
  std::string metric;     ///< flat metric name, e.g. "ape_trans"
  std::string statistic;  ///< e.g. "rmse"
  std::string title;      ///< e.g. "ATE translation RMSE"
  std::string unit;       ///< e.g. "m" (from the runs)
  std::string spec;       ///< e.g. "alignment se2"; empty when the metric has no options to state
};

/// One algorithm's cell in one column: the values of its successful runs (iteration order) and
/// their mean +- std. `best` marks the lowest mean of the column (every metric here is "lower is better").
struct MetricCell {
  std::vector<double> values;
  MeanStd summary;
  bool best = false;
};

/// How an algorithm's runs on one sequence ended.
struct RunCounts {
  std::size_t total = 0;
  std::size_t ok = 0;
  std::size_t failed = 0;
  std::size_t unfinished = 0;  ///< unfinished or unreadable
};

/// One algorithm on one sequence.
struct AlgorithmRow {
  std::string algorithm;
  RunCounts counts;
  std::vector<MetricCell> trajectory_cells;  ///< parallel to SequenceModel::trajectory_columns
  std::vector<MetricCell> map_cells;         ///< parallel to SequenceModel::map_columns
  std::vector<std::size_t> runs;             ///< indices into SweepModel::runs, by iteration
  /// The gallery's run: the median successful run by ATE translation RMSE, or by corner count
  /// when there is no ATE (no reference); the lower middle for an even count. Absent when no run succeeded.
  std::optional<std::size_t> median_run;
  std::string median_by;  ///< "ATE translation RMSE", "corner count" or "" (first successful run)
};

/// Everything the report shows about one sequence.
struct SequenceModel {
  std::string name;
  bool has_reference = false;  ///< some run has a trajectory metric
  std::vector<MetricColumn> trajectory_columns;  ///< Table I: ATE, RPE, relations
  std::vector<MetricColumn> map_columns;         ///< occupied proportion, corners, enclosed areas
  std::vector<AlgorithmRow> rows;                ///< sorted by algorithm name
};

/// The whole sweep, ready to render.
struct SweepModel {
  std::vector<RunRecord> runs;  ///< sorted by run id
  std::vector<SequenceModel> sequences;  ///< sorted by name
  std::vector<std::string> algorithms;   ///< sorted, distinct
  RunCounts counts;
};

/// Groups runs by sequence and algorithm, builds the columns, cells, best marks and median runs.
SweepModel BuildSweepModel(std::vector<RunRecord> runs);

/// The specification a run computed `metric` under, as shown in a column header: "alignment se2"
/// for APE, "delta 1 m" for RPE (from metric_details, else run.json's evaluation), "" otherwise.
std::string MetricSpecLabel(const RunRecord& run, const std::string& metric);

}  // namespace slamsweep::report
