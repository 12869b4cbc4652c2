#include "report/model/significance.h"

#include <algorithm>
#include <fmt/format.h>

#include "evaluator/statistics/holm.h"
#include "evaluator/statistics/mann_whitney.h"
#include "evaluator/statistics/wilcoxon_signed_rank.h"

namespace slamsweep::report::inline model {
namespace {

// The headline column: the relations error where relations exist, else ATE.
std::optional<std::size_t> HeadlineColumn(const SequenceModel& table) {
  for (const char* metric : {"relations_trans", "ape_trans"}) {
    for (std::size_t c = 0; c < table.trajectory_columns.size(); ++c) {
      if (table.trajectory_columns[c].metric == metric) return c;
    }
  }
  return std::nullopt;
}

// Values by iteration seed when every ok run of the row has one ("" seeds make a row unpairable).
std::vector<std::pair<std::string, double>> SeededValues(const SweepModel& model, const AlgorithmRow& row,
                                                         const MetricColumn& column) {
  std::vector<std::pair<std::string, double>> values;
  for (const std::size_t index : row.runs) {
    const RunRecord& run = model.runs[index];
    if (run.status != RunStatus::kOk) continue;
    const std::optional<double> value = run.Metric(column.metric, column.statistic);
    if (!value) continue;
    const auto seed = run.run_spec.find("seed");
    values.emplace_back(seed == run.run_spec.end() ? "" : seed->dump(), *value);
  }
  std::sort(values.begin(), values.end());
  return values;
}

RowTest Compare(const SweepModel& model, const SequenceModel& table, const MetricColumn& column, std::size_t best,
                std::size_t other) {
  RowTest test;
  test.other_row = other;
  test.other = table.rows[other].algorithm;
  const auto a = SeededValues(model, table.rows[best], column);
  const auto b = SeededValues(model, table.rows[other], column);
  std::vector<double> x, y;
  for (const auto& [seed, value] : a) x.push_back(value);
  for (const auto& [seed, value] : b) y.push_back(value);
  test.identical = !x.empty() && !y.empty() &&
                   std::all_of(x.begin(), x.end(), [&](double v) { return v == x.front(); }) &&
                   std::all_of(y.begin(), y.end(), [&](double v) { return v == x.front(); });
  bool same_seeds = a.size() == b.size() && !a.empty();
  for (std::size_t i = 0; same_seeds && i < a.size(); ++i) {
    same_seeds = !a[i].first.empty() && a[i].first == b[i].first;
  }
  if (same_seeds) {
    const evaluator::WilcoxonResult r = evaluator::WilcoxonSignedRank(x, y, evaluator::Alternative::kLess);
    test.test = "Wilcoxon signed-rank";
    test.paired = true;
    test.n = r.pairs_used;
    test.p_value = r.p_value;
    test.min_p = evaluator::WilcoxonMinimumOneSidedP(r.pairs_used);
  } else {
    const evaluator::MannWhitneyResult r = evaluator::MannWhitneyU(x, y, evaluator::Alternative::kLess);
    test.test = "Mann-Whitney U";
    test.n = x.size();
    test.n_other = y.size();
    test.p_value = r.p_value;
    test.min_p = evaluator::MannWhitneyMinimumOneSidedP(x.size(), y.size());
  }
  test.cliffs_delta = evaluator::CliffsDelta(x, y);
  return test;
}

std::string Verdict(const TableSignificance& t, const RowTest& test, double alpha, std::size_t tests) {
  if (test.identical) {
    return fmt::format(
        "tied with {}: every run of both rows gave the same value (identical runs are ties, "
        "not evidence)",
        test.other);
  }
  if (test.p_holm <= alpha) {
    return fmt::format(
        "best, significantly: lower than {} ({}, p = {:.3g}, Holm-adjusted {:.3g}, Cliff's delta "
        "{:.2f})",
        test.other, test.test, test.p_value, test.p_holm, test.cliffs_delta);
  }
  if (test.min_p > alpha / static_cast<double>(tests)) {
    return fmt::format(
        "best, not significantly different from {}: too few runs for any test to reach the level "
        "({} {} reach at best p = {:.3g} against alpha / {} tests = {:.3g}); {} iterations per row "
        "are needed",
        test.other, test.n, test.paired ? "pairs" : "runs", test.min_p, tests, alpha / static_cast<double>(tests),
        t.iterations_needed);
  }
  return fmt::format(
      "best, not significantly different from {} ({}, p = {:.3g}, Holm-adjusted {:.3g}, Cliff's "
      "delta {:.2f})",
      test.other, test.test, test.p_value, test.p_holm, test.cliffs_delta);
}

std::string UnrankedBecause(const AlgorithmRow& row, const MetricColumn& column, const MetricCell& cell) {
  switch (row.kind) {
    case RowKind::kOdometryBaseline:
      return "odometry baseline (the line to beat)";
    case RowKind::kReferenceFloor:
      return "reference floor";
    case RowKind::kPublished:
      return "published figure";
    case RowKind::kContestant:
      break;
  }
  if (row.odometry_is_reference) return "odometry = reference (an upper bound, not a SLAM result)";
  if (!row.flags.empty()) return orchestrator::RunFlagsLabel(row.flags);
  if (row.counts.ok != row.counts.total) {
    return fmt::format("{} of {} runs ok", row.counts.ok, row.counts.total);
  }
  if (cell.summary.n != row.counts.total)
    return fmt::format("a value from {} of {} runs", cell.summary.n, row.counts.total);
  if (!column.best_withheld.empty()) return column.best_withheld;
  return "";
}

std::vector<RankedEntry> Entries(const SequenceModel& table, std::size_t column) {
  const MetricColumn& headline = table.trajectory_columns[column];
  std::vector<RankedEntry> ranked, beside;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const AlgorithmRow& row = table.rows[r];
    const MetricCell& cell = row.trajectory_cells[column];
    RankedEntry entry;
    entry.row = r;
    entry.summary = cell.summary;
    entry.interval = evaluator::StudentTInterval(cell.values);
    entry.n_ok = row.counts.ok;
    entry.n_runs = row.counts.total;
    if (IsBestCandidate(row, headline, cell)) {
      ranked.push_back(entry);
    } else {
      entry.unranked_because = UnrankedBecause(row, headline, cell);
      if (entry.unranked_because.empty()) entry.unranked_because = "not a candidate";
      beside.push_back(entry);
    }
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const RankedEntry& a, const RankedEntry& b) { return a.summary.mean < b.summary.mean; });
  for (std::size_t i = 0; i < ranked.size(); ++i) ranked[i].rank = i + 1;
  ranked.insert(ranked.end(), beside.begin(), beside.end());
  return ranked;
}

}  // namespace

std::size_t IterationsNeeded(double level, bool paired) {
  for (std::size_t n = 1; n <= 64; ++n) {
    const double min_p = paired ? evaluator::WilcoxonMinimumOneSidedP(n) : evaluator::MannWhitneyMinimumOneSidedP(n, n);
    if (min_p <= level) return n;
  }
  return 65;
}

std::vector<TableSignificance> BuildSignificance(const SweepModel& model, double alpha) {
  std::vector<TableSignificance> tables;
  for (const SequenceModel& table : model.sequences) {
    TableSignificance t;
    t.table_key = table.key;
    t.table_title = table.title;
    const std::optional<std::size_t> column = HeadlineColumn(table);
    if (!column) {
      t.verdict = "no headline metric: this table has only ground-truth-free metrics (no relations, no ATE)";
      tables.push_back(std::move(t));
      continue;
    }
    const MetricColumn& headline = table.trajectory_columns[*column];
    t.metric_title = headline.title;
    t.column = column;
    t.entries = Entries(table, *column);
    std::vector<std::pair<double, std::size_t>> ranked;
    std::optional<std::size_t> baseline;
    for (std::size_t r = 0; r < table.rows.size(); ++r) {
      const AlgorithmRow& row = table.rows[r];
      const MetricCell& cell = row.trajectory_cells[*column];
      if (row.kind == RowKind::kOdometryBaseline && !cell.values.empty()) baseline = r;
      if (IsBestCandidate(row, headline, cell)) ranked.emplace_back(cell.summary.mean, r);
    }
    std::sort(ranked.begin(), ranked.end());
    if (ranked.empty()) {
      t.verdict = "no row may be ranked (every row is a baseline, flagged, or has failed runs)";
    } else {
      t.best_row = ranked.front().second;
      if (ranked.size() > 1) t.vs_runner_up = Compare(model, table, headline, *t.best_row, ranked[1].second);
      if (baseline) t.vs_baseline = Compare(model, table, headline, *t.best_row, *baseline);
      if (!t.vs_runner_up) t.verdict = "the only ranked row: nothing to compare it with";
    }
    tables.push_back(std::move(t));
  }
  // Holm over every test of the report, then the verdicts (which name the family's size).
  std::vector<RowTest*> family;
  for (TableSignificance& t : tables) {
    for (std::optional<RowTest>* test : {&t.vs_runner_up, &t.vs_baseline}) {
      if (*test && !(*test)->identical) family.push_back(&**test);
    }
  }
  std::vector<double> p;
  for (const RowTest* test : family) p.push_back(test->p_value);
  const std::vector<double> adjusted = evaluator::HolmAdjusted(p);
  for (std::size_t i = 0; i < family.size(); ++i) family[i]->p_holm = adjusted[i];
  const std::size_t tests = std::max<std::size_t>(1, family.size());
  for (TableSignificance& t : tables) {
    if (!t.vs_runner_up) continue;
    if (t.vs_runner_up->min_p > alpha / static_cast<double>(tests)) {
      t.iterations_needed = IterationsNeeded(alpha / static_cast<double>(tests), t.vs_runner_up->paired);
    }
    t.verdict = Verdict(t, *t.vs_runner_up, alpha, tests);
  }
  return tables;
}

}  // namespace slamsweep::report::inline model
