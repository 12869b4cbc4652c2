#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "evaluator/statistics/mean_interval.h"
#include "report/model/sweep_model.h"

namespace slamsweep::report::inline model {

/// One one-sided test: are the best row's values lower than another row's?
struct RowTest {
  std::size_t other_row = 0;  ///< index into SequenceModel::rows
  std::string other;          ///< the other row's label
  /// "Wilcoxon signed-rank" (runs paired by iteration seed) or "Mann-Whitney U".
  std::string test;
  bool paired = false;
  std::size_t n = 0;          ///< pairs used (paired: non-zero differences) or the best row's runs
  std::size_t n_other = 0;    ///< the other row's runs (unpaired) or 0
  double p_value = 1.0;       ///< one-sided
  double p_holm = 1.0;        ///< Holm-adjusted over every test of the report
  double cliffs_delta = 0.0;  ///< of the best row against the other: negative when the best row is lower
  /// The smallest p-value these run counts can reach (5 pairs: 1/32).
  double min_p = 1.0;
  /// Every value of both rows equal: identical runs (a deterministic program without noise) are ties.
  bool identical = false;
};

/// One row of a table's ranking on the headline metric.
struct RankedEntry {
  std::size_t row = 0;                              ///< index into SequenceModel::rows
  std::optional<std::size_t> rank;                  ///< 1 = best; none for rows shown beside the ranking
  MeanStd summary;                                  ///< of the row's values of the headline metric
  std::optional<evaluator::MeanInterval> interval;  ///< 95 % Student t interval (two or more values)
  std::size_t n_ok = 0;
  std::size_t n_runs = 0;
  /// Why the row is shown but not ranked ("odometry baseline", "stale", "4 of 5 runs ok", ...); "" when ranked.
  std::string unranked_because;
};

/// The significance of one table's "best" on its headline metric.
struct TableSignificance {
  std::string table_key;  ///< SequenceModel::key
  std::string table_title;
  /// The headline: the relations error where the table has it, else ATE; "" when only ground-truth-free
  /// metrics exist (then nothing is tested and `verdict` says so).
  std::string metric_title;
  std::optional<std::size_t> column;  ///< the headline's index in SequenceModel::trajectory_columns
  /// Ranked rows by mean (lowest first), then the rows shown beside the ranking.
  std::vector<RankedEntry> entries;
  std::optional<std::size_t> best_row;
  std::optional<RowTest> vs_runner_up;
  std::optional<RowTest> vs_baseline;  ///< against the odometry baseline row, when the table has one
  /// "best, significantly", "best, not significantly different from X", "too few runs ..." etc.
  std::string verdict;
  /// Iterations per row at which the runner-up test could reach the level after Holm (0 when reachable).
  std::size_t iterations_needed = 0;
};

/// Every table's significance: one-sided tests of the best row against the runner-up and the odometry
/// baseline (Wilcoxon signed-rank where both rows ran the same iteration seeds, else Mann-Whitney U), Holm-
/// corrected across all tests of the report at level `alpha`, with Cliff's delta.
std::vector<TableSignificance> BuildSignificance(const SweepModel& model, double alpha = 0.05);

/// The iterations per row a one-sided test needs before its smallest reachable p-value is at most
/// `level` (paired: 1/2^n; unpaired: 1/C(2n, n)).
std::size_t IterationsNeeded(double level, bool paired);

}  // namespace slamsweep::report::inline model
