#include "orchestrator/history/night.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/history/series_odometry.h"
#include "orchestrator/run/run_json.h"
#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator::inline history {
namespace {

/// Orders a night's series: algorithm, sequence, noise, odometry, metric, statistic.
using SeriesOrder = std::tuple<std::string, std::string, std::string, std::string, std::string, std::string>;
using CellKey = std::tuple<std::string, std::string, std::string, std::string>;

}  // namespace

Night ReadNight(const std::filesystem::path& result_dir, const std::string& label) {
  const std::filesystem::path absolute = std::filesystem::absolute(result_dir).lexically_normal();
  const std::filesystem::path database = absolute / "results.sqlite";
  if (!std::filesystem::exists(database)) {
    throw evaluator::InputError(
        fmt::format("{}: no results database; expected the output directory of "
                    "`slamsweep run` or `slamsweep merge`",
                    database.string()));
  }
  const ResultsStore store = ResultsStore::OpenExisting(database);
  const std::vector<StoredSweep> sweeps = store.Sweeps();
  if (sweeps.empty()) {
    throw evaluator::InputError(
        fmt::format("{}: no sweep recorded; expected at least one `slamsweep run` into it", database.string()));
  }
  Night night;
  night.result_dir = absolute;
  night.sweep_id = sweeps.back().id;
  night.sweep_name = sweeps.back().info.name;
  night.started_at = sweeps.front().info.started_at;
  for (const StoredSweep& sweep : sweeps) {
    // A merged directory holds one sweep per shard; the night starts with the first of them.
    if (!sweep.info.started_at.empty() && (night.started_at.empty() || sweep.info.started_at < night.started_at)) {
      night.started_at = sweep.info.started_at;
    }
  }
  night.label = label.empty() ? night.started_at : label;
  if (night.label.empty()) night.label = fmt::format("{}#{}", absolute.string(), night.sweep_id);
  night.report_index = absolute / "report" / "index.html";

  std::map<SeriesOrder, SampleSeries> series;
  std::map<CellKey, CellCounts> cells;
  // Runs() is ordered by iteration within a cell, so samples keep the iteration order.
  for (const RunRecord& run : store.Runs()) {
    // Runs with other parameter values are another series: never pooled into one sample.
    const std::string algorithm = AlgorithmLabel(run.algorithm, run.parameters);
    // Nor are runs on the recorded odometry pooled with runs handed the reference.
    const std::string odometry = OdometryModeOfRunJson(run.run_spec);
    CellCounts& cell = cells[{algorithm, run.sequence, run.noise, odometry}];
    cell.algorithm = algorithm;
    cell.sequence = run.sequence;
    cell.noise = run.noise;
    cell.odometry = odometry;
    if (run.status != RunStatus::kOk) {
      ++cell.failed_runs;
      continue;
    }
    ++cell.ok_runs;
    for (const FlatMetric& metric : run.metrics) {
      SampleSeries& s = series[{algorithm, run.sequence, run.noise, odometry, metric.metric, metric.statistic}];
      if (s.metric.empty()) {
        s.algorithm = algorithm;
        s.sequence = run.sequence;
        s.noise = run.noise;
        s.odometry = odometry;
        s.metric = metric.metric;
        s.statistic = metric.statistic;
        s.unit = metric.unit;
      }
      if (metric.value.has_value() && std::isfinite(*metric.value)) s.values.push_back(*metric.value);
    }
  }
  for (auto& [key, s] : series) night.series.push_back(std::move(s));
  for (auto& [key, c] : cells) night.cells.push_back(std::move(c));
  return night;
}

bool SameSeries(const SeriesKey& a, const SeriesKey& b) {
  return a.algorithm == b.algorithm && a.sequence == b.sequence && a.noise == b.noise && a.odometry == b.odometry &&
         a.metric == b.metric && a.statistic == b.statistic;
}

std::string SeriesName(const SeriesKey& key) {
  return fmt::format("{} / {} / {} / {} odometry: {}.{}", key.algorithm, key.sequence, key.noise, key.odometry,
                     key.metric, key.statistic);
}

const SampleSeries* FindSeries(const Night& night, const SeriesKey& key) {
  const auto it =
      std::find_if(night.series.begin(), night.series.end(), [&](const SampleSeries& s) { return SameSeries(s, key); });
  return it == night.series.end() ? nullptr : &*it;
}

}  // namespace slamsweep::orchestrator::inline history
