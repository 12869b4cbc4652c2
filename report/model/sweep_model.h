#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "evaluator/sequence/scan_spacing.h"
#include "evaluator/validity/metric_validity.h"
#include "report/model/mean_std.h"
#include "report/model/published_figures.h"
#include "orchestrator/run/run_record.h"

namespace slamsweep::report::inline model {

using orchestrator::FlatMetric;
using orchestrator::RunOutputs;
using orchestrator::RunRecord;
using orchestrator::RunStatus;
using orchestrator::RunStatusName;

struct AlgorithmRow;
struct MetricColumn;
struct MetricCell;
/// Whether a row may be ranked and marked best: a contestant (not a baseline or reference line)
/// without any run mark (odometry = reference, stale, unisolated) whose every run succeeded
/// (n_ok = n_runs: a row that failed some draws must not win on its lucky ones).
bool IsBestCandidate(const AlgorithmRow& row);
/// Whether one cell may be best: its row is a candidate, its column may mark a best (the validity
/// study supports the metric, see MetricColumn::best_withheld) and every run of the row has a value.
/// Every best mark and ranking of the report goes through here.
bool IsBestCandidate(const AlgorithmRow& row, const MetricColumn& column, const MetricCell& cell);

/// One table column: one flat metric computed under one specification. Runs whose
/// specifications differ (say alignment se2 and sim2) get separate columns, because numbers from
/// different specifications must never share a column (spec/metrics.md).
struct MetricColumn {
  std::string metric;     ///< flat metric name, e.g. "ape_trans"
  std::string statistic;  ///< e.g. "rmse"
  std::string title;      ///< e.g. "ATE translation RMSE"
  std::string unit;       ///< e.g. "m" (from the runs)
  std::string spec;       ///< e.g. "alignment se2"; empty when the metric has no options to state
  /// Why no cell of the column is marked best, "" when one may be: a ground-truth-free metric whose
  /// validity study does not show that it tracks the error (report/model/validity_support.h).
  std::string best_withheld;
};

/// One row's cell in one column: the values of its successful runs (iteration order) and their
/// mean +- std. `best` marks the lowest mean of the column among the cells IsBestCandidate admits
/// (every metric here is "lower is better").
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

/// What a row is to the comparison: only contestants are ranked and marked best; the other kinds are
/// drawn beside them as reference lines.
enum class RowKind {
  kContestant,        ///< a SLAM program's runs
  kOdometryBaseline,  ///< the odometry baseline (adapter "odometry"): dead reckoning, the line to beat
  kReferenceFloor,    ///< the reference trajectory itself, scored by the table's metrics
  kPublished,         ///< a published figure for the same data, with its citation
};

/// One comparison group: an algorithm with one set of parameter values, computed by one build, on the
/// table's sequence and noise setting. Runs of other parameter values or builds are other rows,
/// never pooled into this one.
struct AlgorithmRow {
  /// What the row is called everywhere (tables, legends, galleries, file folders): the algorithm's
  /// name, followed by "[k=v;...]" of the parameters whose values differ between its rows in the sweep.
  std::string algorithm;
  /// The algorithm's name alone, and all its parameters ("k=v;...").
  std::string name;
  std::string parameters;
  /// Some run of the row got the reference as odometry: an upper bound, not a SLAM result.
  bool odometry_is_reference = false;
  /// The union of the row's run marks: a flagged row is shown, never marked best.
  orchestrator::RunFlags flags;
  RowKind kind = RowKind::kContestant;
  /// BuildSignature of the row's runs; rows of one algorithm and parameters computed by different
  /// builds are separate rows (`build_split`), labelled with it and never pooled.
  std::string build;
  bool build_split = false;
  std::string build_description;  ///< BuildDescriptionOfRunJson, for the note of a split row
  /// "seeded", "deterministic", "unseeded" or "mixed"; "" when not recorded.
  std::string seeding;
  RunCounts counts;
  std::vector<MetricCell> trajectory_cells;  ///< parallel to SequenceModel::trajectory_columns
  std::vector<MetricCell> map_cells;         ///< parallel to SequenceModel::map_columns
  std::vector<std::size_t> runs;             ///< indices into SweepModel::runs, by iteration
  /// The gallery's run: the median successful run by ATE translation RMSE, or by corner count
  /// when there is no ATE (no reference); the lower middle for an even count. Absent when no run succeeded.
  std::optional<std::size_t> median_run;
  std::string median_by;  ///< "ATE translation RMSE", "corner count" or "" (first successful run)
  /// A reference line measured on other data than the table's (a published figure over the whole log beside
  /// a table of part of it): what the difference is. Empty otherwise.
  std::string scope_note;
};

/// One comparison table: a sequence under one noise setting. Rows are compared only within it.
struct SequenceModel {
  std::string name;  ///< the sequence
  std::string noise;
  /// "<sequence>/<noise>": unique per table, the key of its page and plots.
  std::string key;
  /// For headings: "intel, noise odo-low".
  std::string title;
  bool has_reference = false;  ///< some run has a trajectory metric
  /// The relations the runs were scored on: inside the (cut) log, and of the relations file outside it
  /// (a log of part of a run; shown as "outside the log", never as missed). From the first run that has them.
  std::optional<std::size_t> relations_inside_log;
  std::size_t relations_outside_log = 0;
  std::vector<MetricColumn> trajectory_columns;  ///< Table I: ATE, RPE, relations
  std::vector<MetricColumn> map_columns;         ///< occupied proportion, corners, enclosed areas
  std::vector<AlgorithmRow> rows;                ///< sorted by name, then parameters
  /// How far apart the table's scans are (TableScanSpacing); absent when no run recorded it.
  std::optional<evaluator::ScanSpacing> scan_spacing;
};

/// What BuildSweepModel weighs beside the runs.
struct SweepModelOptions {
  /// A validity study the sweep named (validity_study: in its file, copied to the result
  /// directory): it supports ground-truth-free metrics on sequences without a reference when the
  /// sweep's own runs study no other sequence.
  std::optional<evaluator::ValidityStudy> named_study;
  std::string named_study_source;  ///< where it came from, for notes
  /// Published relations errors (configs/published.yaml) drawn as rows beside a table whose runs score a whole
  /// log against that log's relations file; never ranked.
  std::vector<PublishedFigure> published;
  /// summary.json's "validity" (with its inputs_sha256), when the result directory has one: the model takes
  /// the study from it when it was computed from these very runs by this very build, and computes it
  /// otherwise (orchestrator::StoredValidityStudyFor).
  std::optional<nlohmann::json> stored_validity;
};

/// The whole sweep, ready to render.
struct SweepModel {
  std::vector<RunRecord> runs;           ///< sorted by run id
  std::vector<SequenceModel> sequences;  ///< one per sequence x noise, sorted by sequence, then noise
  std::vector<std::string> algorithms;   ///< names, sorted, distinct
  /// The sweep's name (run.json's "sweep"; the names joined by ", " when a merged directory holds several).
  std::string sweep_name;
  RunCounts counts;
  /// The metric validity study of these runs (validity.html shows it; best marks of map metrics rest on it).
  evaluator::ValidityStudy validity;
};

/// Groups runs by sequence x noise (a table) and algorithm x parameters (a row), builds the columns,
/// cells, best marks and median runs.
SweepModel BuildSweepModel(std::vector<RunRecord> runs, const SweepModelOptions& options = {});

/// The specification a run computed `metric` under, as shown in a column header: "alignment se2"
/// for APE, "delta 1 m" for RPE (from metric_details, else run.json's evaluation), "" otherwise.
std::string MetricSpecLabel(const RunRecord& run, const std::string& metric);

}  // namespace slamsweep::report::inline model
