#include "report/model/across_data_sets.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>
#include <fmt/format.h>

#include "evaluator/statistics/rank_correlation.h"

namespace slamsweep::report::inline model {
namespace {

using RowKey = std::tuple<std::string, std::string, std::string>;  // name, parameters, build

std::string OdometryOf(const SweepModel& model, const AlgorithmRow& row) {
  return row.runs.empty() ? std::string() : model.runs[row.runs.front()].odometry;
}

// The run.json "sequence" field `key` of the table's first run that has it ("" when none).
std::string SequenceField(const SweepModel& model, const SequenceModel& table, const char* key) {
  for (const AlgorithmRow& row : table.rows) {
    for (const std::size_t index : row.runs) {
      const nlohmann::json& spec = model.runs[index].run_spec;
      const auto sequence = spec.find("sequence");
      if (sequence == spec.end() || !sequence->is_object()) continue;
      const auto value = sequence->find(key);
      if (value != sequence->end() && value->is_string()) return value->get<std::string>();
    }
  }
  return "";
}

// The highest scan rate recorded by a run of the table (its runs share the log; noise does not change the rate).
std::optional<double> ScanRate(const SweepModel& model, const SequenceModel& table) {
  std::optional<double> rate;
  for (const AlgorithmRow& row : table.rows) {
    for (const std::size_t index : row.runs) {
      const std::optional<double> r = model.runs[index].scan_rate_hz;
      if (r && (!rate || *r > *rate)) rate = r;
    }
  }
  return rate;
}

std::string RateText(const std::optional<double>& rate) {
  return rate ? fmt::format("{:.2f} scans/s", *rate) : std::string("scan rate not recorded");
}

// A table that may count: its physical run (the relations file, else the table itself) and its scan rate.
struct Eligible {
  std::size_t choice = 0;  // index into DataSetVerdict::data_sets
  std::size_t table = 0;   // index into SweepModel::sequences
  std::string run;
  std::string relations;
  std::optional<double> rate;
};

// Whether the table's headline measures error against an independent reference, and the reason either way.
bool Independent(const SweepModel& model, const SequenceModel& table, const TableSignificance& t, std::string& why) {
  if (!t.column) {
    why = "no reference: only ground-truth-free metrics";
    return false;
  }
  const std::string& metric = table.trajectory_columns[*t.column].metric;
  if (metric == "relations_trans") {
    why = "relations (Kuemmerle et al.): independent of every program";
    return true;
  }
  const std::string ground_truth = SequenceField(model, table, "ground_truth");
  if (ground_truth == "exact") {
    why = "ATE against exact ground truth (a simulated run)";
    return true;
  }
  if (ground_truth == "corrected_poses") {
    why = "ATE against a corrected log: GMapping's output, so it measures agreement with GMapping, not error";
  } else {
    why = "ATE against a reference of kind \"" + (ground_truth.empty() ? std::string("unrecorded") : ground_truth) +
          "\", not independent ground truth";
  }
  return false;
}

// Marks the used tables: one per physical run, the one with the most scans per second.
void ChooseDensest(std::vector<Eligible>& eligible, DataSetVerdict& verdict) {
  std::map<std::string, std::vector<const Eligible*>> by_run;
  for (const Eligible& e : eligible) by_run[e.run].push_back(&e);
  for (const auto& [run, tables] : by_run) {
    const Eligible* densest = tables.front();
    for (const Eligible* e : tables) {
      if (e->rate && (!densest->rate || *e->rate > *densest->rate)) densest = e;
    }
    verdict.data_sets[densest->choice].used = true;
    for (const Eligible* e : tables) {
      if (e == densest) continue;
      DataSetChoice& choice = verdict.data_sets[e->choice];
      choice.used = false;
      const std::string& kept = verdict.data_sets[densest->choice].table_title;
      const std::string relations = std::filesystem::path(e->relations).filename().string();
      choice.why = densest->rate ? fmt::format(
                                       "the same physical run as {} (both scored on {}): a run counts once, by "
                                       "its densest log ({}, against {} here)",
                                       kept, relations, RateText(densest->rate), RateText(e->rate))
                                 : fmt::format(
                                       "the same physical run as {} (both scored on {}): a run counts once; "
                                       "their runs did not record scan rates, so the first by name counts "
                                       "(run them again to choose the densest)",
                                       kept, relations);
    }
  }
}

std::string Joined(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i)
    out += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
  return out;
}

void Conclude(DataSetVerdict& v) {
  const std::size_t n = v.used.size();
  const std::size_t k = v.contestants.size();
  if (n < 2) {
    v.verdict = n == 1 ? "one data set (" + v.used.front() + ") in this setting: its own ranking below is the answer"
                       : "no data set in this setting measures error against an independent reference";
    return;
  }
  if (k < 2) {
    v.verdict = "fewer than two rows are ranked on every data set: nothing to compare";
    return;
  }
  if (v.sign_test) {
    const evaluator::SignTestResult& s = *v.sign_test;
    v.verdict = fmt::format(
        "two contestants: {} is lower on {} of {} data sets ({} against, {} tied); one-sided sign test p = {:.3g}{}",
        v.contestants[0].label, s.wins, n, s.losses, s.ties, s.p_value,
        s.p_value <= v.alpha ? "" : ": no difference shown");
    return;
  }
  const evaluator::FriedmanResult& f = v.friedman;
  const double spread = v.contestants.back().mean_rank - v.contestants.front().mean_rank;
  std::string text;
  if (f.all_tied) {
    text = "every contestant has the same value on every data set: no difference";
  } else if (f.iman_davenport_p > v.alpha) {
    text = fmt::format("no difference shown over {} data sets (Iman-Davenport F = {:.3g}, p = {:.3g})", n,
                       f.iman_davenport_f, f.iman_davenport_p);
  } else if (v.different.empty()) {
    text = fmt::format(
        "the contestants differ (Iman-Davenport F = {:.3g}, p = {:.3g}), but no pair's mean ranks differ by "
        "Nemenyi's critical difference ({:.2f})",
        f.iman_davenport_f, f.iman_davenport_p, v.critical_difference);
  } else {
    std::vector<std::string> claims;
    for (std::size_t i = 0; i < k; ++i) {
      std::vector<std::string> worse;
      for (const auto& [a, b] : v.different) {
        if (a == i) worse.push_back(v.contestants[b].label);
      }
      if (!worse.empty()) claims.push_back(v.contestants[i].label + " is better than " + Joined(worse));
    }
    text = fmt::format(
        "the contestants differ (Iman-Davenport F = {:.3g}, p = {:.3g}); by Nemenyi's critical "
        "difference ({:.2f}): {}",
        f.iman_davenport_f, f.iman_davenport_p, v.critical_difference, Joined(claims));
  }
  if (v.data_sets_for_any_difference > 0) {
    text += fmt::format(
        ". With {} data sets and {} contestants the critical difference ({:.2f} ranks) exceeds the largest possible "
        "difference ({} ranks): no pair can be told apart; at least {} data sets are needed before any pair could",
        n, k, v.critical_difference, k - 1, v.data_sets_for_any_difference);
    if (v.data_sets_for_observed_difference > 0) {
      text += fmt::format(", {} for the spread seen here ({:.2f} ranks)", v.data_sets_for_observed_difference, spread);
    }
  } else if (v.data_sets_for_observed_difference > 0 && v.different.empty()) {
    text +=
        fmt::format(". The spread seen here ({:.2f} ranks) would need {} data sets to reach the critical difference",
                    spread, v.data_sets_for_observed_difference);
  }
  v.verdict = text;
}

void Test(DataSetVerdict& v) {
  const std::size_t n = v.used.size();
  const std::size_t k = v.contestants.size();
  if (n < 2 || k < 2) return;
  std::vector<std::vector<double>> values(n, std::vector<double>(k));
  for (std::size_t d = 0; d < n; ++d) {
    for (std::size_t j = 0; j < k; ++j) values[d][j] = v.contestants[j].values[d];
  }
  for (std::size_t d = 0; d < n; ++d) {
    const std::vector<double> ranks = evaluator::AverageRanks(values[d]);
    for (std::size_t j = 0; j < k; ++j) v.contestants[j].ranks.push_back(ranks[j]);
  }
  const evaluator::FriedmanResult friedman = evaluator::FriedmanTest(values);
  for (std::size_t j = 0; j < k; ++j) v.contestants[j].mean_rank = friedman.mean_ranks[j];
  std::stable_sort(v.contestants.begin(), v.contestants.end(),
                   [](const DataSetContestant& a, const DataSetContestant& b) { return a.mean_rank < b.mean_rank; });
  if (k == 2) {  // the sign test of the lower mean rank against the other
    v.sign_test = evaluator::OneSidedSignTest(v.contestants[0].values, v.contestants[1].values);
    return;
  }
  v.tested = true;
  for (std::size_t d = 0; d < n; ++d) {  // again in the sorted order, so that friedman.mean_ranks follow it
    for (std::size_t j = 0; j < k; ++j) values[d][j] = v.contestants[j].values[d];
  }
  v.friedman = evaluator::FriedmanTest(values);
  v.critical_difference = evaluator::NemenyiCriticalDifference(k, n, v.alpha);
  if (!v.friedman.all_tied && v.friedman.iman_davenport_p <= v.alpha) {
    for (std::size_t a = 0; a < k; ++a) {
      for (std::size_t b = a + 1; b < k; ++b) {
        if (v.contestants[b].mean_rank - v.contestants[a].mean_rank >= v.critical_difference)
          v.different.emplace_back(a, b);
      }
    }
  }
  const double largest = static_cast<double>(k - 1);
  if (v.critical_difference > largest) {
    v.data_sets_for_any_difference = evaluator::DataSetsNeeded(k, largest, v.alpha);
  }
  const double spread = v.contestants.back().mean_rank - v.contestants.front().mean_rank;
  if (spread > 0.0 && spread < v.critical_difference) {
    v.data_sets_for_observed_difference = evaluator::DataSetsNeeded(k, spread, v.alpha);
  }
}

DataSetVerdict BuildVerdict(const SweepModel& model, const std::vector<TableSignificance>& significance,
                            const std::string& noise, const std::string& odometry, double alpha) {
  DataSetVerdict v;
  v.noise = noise;
  v.odometry = odometry;
  v.alpha = alpha;
  std::vector<Eligible> eligible;
  std::vector<std::size_t> tables;
  for (std::size_t s = 0; s < model.sequences.size() && s < significance.size(); ++s) {
    const SequenceModel& table = model.sequences[s];
    if (table.noise != noise) continue;
    const bool in_setting = std::any_of(table.rows.begin(), table.rows.end(), [&](const AlgorithmRow& row) {
      return row.kind == RowKind::kContestant && OdometryOf(model, row) == odometry;
    });
    if (!in_setting) continue;
    DataSetChoice choice{table.key, table.title, "", false, ""};
    if (const std::optional<std::size_t> column = significance[s].column) {
      const MetricColumn& headline = table.trajectory_columns[*column];
      choice.metric = headline.title + (headline.unit.empty() ? "" : " (" + headline.unit + ")");
    }
    if (Independent(model, table, significance[s], choice.why)) {
      const std::string relations = SequenceField(model, table, "relations");
      eligible.push_back({v.data_sets.size(), s, relations.empty() ? "table " + table.key : "relations " + relations,
                          relations, ScanRate(model, table)});
    }
    v.data_sets.push_back(std::move(choice));
    tables.push_back(s);
  }
  ChooseDensest(eligible, v);
  // The ranked rows of each used table, by contestant.
  std::vector<std::size_t> used_tables;
  for (std::size_t i = 0; i < v.data_sets.size(); ++i) {
    if (!v.data_sets[i].used) continue;
    used_tables.push_back(tables[i]);
    v.used.push_back(v.data_sets[i].table_title);
    v.used_metrics.push_back(v.data_sets[i].metric);
  }
  std::map<RowKey, std::vector<const RankedEntry*>> entries;  // per used table, null when absent
  std::map<RowKey, std::string> labels;
  std::vector<RowKey> order;
  for (std::size_t u = 0; u < used_tables.size(); ++u) {
    const SequenceModel& table = model.sequences[used_tables[u]];
    for (const RankedEntry& entry : significance[used_tables[u]].entries) {
      const AlgorithmRow& row = table.rows[entry.row];
      if (row.kind != RowKind::kContestant || OdometryOf(model, row) != odometry) continue;
      const RowKey key{row.name, row.parameters, row.build};
      auto [it, inserted] = entries.try_emplace(key, used_tables.size(), nullptr);
      if (inserted) order.push_back(key), labels[key] = row.algorithm;
      it->second[u] = &entry;
    }
  }
  std::sort(order.begin(), order.end());
  for (const RowKey& key : order) {
    const std::vector<const RankedEntry*>& found = entries.at(key);
    std::string missing;
    DataSetContestant contestant{labels.at(key), 0.0, {}, {}};
    for (std::size_t u = 0; u < found.size() && missing.empty(); ++u) {
      const std::string& title = model.sequences[used_tables[u]].title;
      if (!found[u]) {
        missing = "not run on " + title;
      } else if (!found[u]->rank) {
        missing = "not ranked on " + title + " (" + found[u]->unranked_because + ")";
      } else {
        contestant.values.push_back(found[u]->summary.mean);
      }
    }
    if (missing.empty()) {
      v.contestants.push_back(std::move(contestant));
    } else {
      v.left_out.push_back(labels.at(key) + ": " + missing);
    }
  }
  Test(v);
  Conclude(v);
  return v;
}

}  // namespace

std::vector<DataSetVerdict> BuildAcrossDataSets(const SweepModel& model,
                                                const std::vector<TableSignificance>& significance, double alpha) {
  std::set<std::pair<std::string, std::string>> settings;  // noise, odometry mode
  std::vector<std::pair<std::string, std::string>> ordered;
  for (const SequenceModel& table : model.sequences) {
    for (const AlgorithmRow& row : table.rows) {
      if (row.kind != RowKind::kContestant) continue;
      if (settings.emplace(table.noise, OdometryOf(model, row)).second)
        ordered.emplace_back(table.noise, OdometryOf(model, row));
    }
  }
  std::vector<DataSetVerdict> verdicts;
  for (const auto& [noise, odometry] : ordered)
    verdicts.push_back(BuildVerdict(model, significance, noise, odometry, alpha));
  return verdicts;
}

}  // namespace slamsweep::report::inline model
