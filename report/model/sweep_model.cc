#include "report/model/sweep_model.h"

#include <algorithm>
#include <limits>
#include <map>
#include <set>

namespace slamsweep::report {

namespace {

using nlohmann::json;

struct ColumnCandidate {
  const char* metric;
  const char* statistic;
  const char* title;
};

// Table I of the paper (trajectory RMSE), then RPE and the relations metric of Kuemmerle et al.
constexpr ColumnCandidate kTrajectoryCandidates[] = {
    {"ape_trans", "rmse", "ATE translation RMSE"},    {"ape_rot", "rmse", "ATE rotation RMSE"},
    {"rpe_trans", "rmse", "RPE translation RMSE"},    {"rpe_rot", "rmse", "RPE rotation RMSE"},
    {"relations_trans", "mean", "Relations translation mean"}, {"relations_rot", "mean", "Relations rotation mean"},
};

// The three ground-truth-free metrics (paper sections III.A-C).
constexpr ColumnCandidate kMapCandidates[] = {
    {"occupied_to_free_unknown", "value", "Occupied proportion (occupied / free+unknown)"},
    {"corners", "value", "Corners"},
    {"enclosed_areas", "value", "Enclosed areas"},
};

std::string JsonScalarText(const json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_integer()) return std::to_string(value.get<long long>());
  if (value.is_number()) {
    json copy = value;
    std::string text = copy.dump();
    // 1.0 -> "1": a header reads "delta 1 m", not "delta 1.0 m".
    if (text.size() > 2 && text.ends_with(".0")) text.resize(text.size() - 2);
    return text;
  }
  return value.dump();
}

const json* Find(const json& object, const char* key) {
  if (!object.is_object()) return nullptr;
  const auto it = object.find(key);
  if (it == object.end() || it->is_null()) return nullptr;
  return &*it;
}

std::vector<MetricColumn> BuildColumns(const std::vector<RunRecord>& runs, const std::vector<std::size_t>& indices,
                                       std::span<const ColumnCandidate> candidates) {
  std::vector<MetricColumn> columns;
  for (const ColumnCandidate& candidate : candidates) {
    std::vector<std::string> specs;  // first-appearance order
    std::string unit;
    for (std::size_t index : indices) {
      const RunRecord& run = runs[index];
      if (run.status != RunStatus::kOk || !run.Metric(candidate.metric, candidate.statistic)) continue;
      if (unit.empty()) unit = run.MetricUnit(candidate.metric, candidate.statistic);
      std::string spec = MetricSpecLabel(run, candidate.metric);
      if (std::find(specs.begin(), specs.end(), spec) == specs.end()) specs.push_back(std::move(spec));
    }
    for (std::string& spec : specs) {
      columns.push_back({candidate.metric, candidate.statistic, candidate.title, unit, std::move(spec)});
    }
  }
  return columns;
}

MetricCell BuildCell(const std::vector<RunRecord>& runs, const std::vector<std::size_t>& indices,
                     const MetricColumn& column) {
  MetricCell cell;
  for (std::size_t index : indices) {
    const RunRecord& run = runs[index];
    if (run.status != RunStatus::kOk) continue;
    const std::optional<double> value = run.Metric(column.metric, column.statistic);
    if (!value || MetricSpecLabel(run, column.metric) != column.spec) continue;
    cell.values.push_back(*value);
  }
  cell.summary = ComputeMeanStd(cell.values);
  return cell;
}

void MarkBest(std::vector<AlgorithmRow>& rows, std::vector<MetricCell> AlgorithmRow::* cells, std::size_t columns) {
  for (std::size_t c = 0; c < columns; ++c) {
    double best = std::numeric_limits<double>::infinity();
    for (const AlgorithmRow& row : rows) {
      const MetricCell& cell = (row.*cells)[c];
      if (cell.summary.n > 0) best = std::min(best, cell.summary.mean);
    }
    for (AlgorithmRow& row : rows) {
      MetricCell& cell = (row.*cells)[c];
      cell.best = cell.summary.n > 0 && cell.summary.mean == best;
    }
  }
}

// Lower middle of the successful runs ordered by the metric: a real run, never an average.
std::optional<std::size_t> MedianRunBy(const std::vector<RunRecord>& runs, const std::vector<std::size_t>& indices,
                                       const char* metric, const char* statistic) {
  std::vector<std::pair<double, std::size_t>> ranked;
  for (std::size_t index : indices) {
    const RunRecord& run = runs[index];
    if (run.status != RunStatus::kOk) continue;
    if (const std::optional<double> value = run.Metric(metric, statistic)) ranked.emplace_back(*value, index);
  }
  if (ranked.empty()) return std::nullopt;
  std::sort(ranked.begin(), ranked.end());
  return ranked[(ranked.size() - 1) / 2].second;
}

void ChooseMedianRun(const std::vector<RunRecord>& runs, AlgorithmRow& row) {
  if ((row.median_run = MedianRunBy(runs, row.runs, "ape_trans", "rmse"))) {
    row.median_by = "ATE translation RMSE";
  } else if ((row.median_run = MedianRunBy(runs, row.runs, "corners", "value"))) {
    row.median_by = "corner count";
  } else {
    for (std::size_t index : row.runs) {
      if (runs[index].status == RunStatus::kOk) {
        row.median_run = index;
        break;
      }
    }
  }
}

void Count(const RunRecord& run, RunCounts& counts) {
  ++counts.total;
  switch (run.status) {
    case RunStatus::kOk:
      ++counts.ok;
      break;
    case RunStatus::kFailed:
      ++counts.failed;
      break;
    case RunStatus::kUnfinished:
    case RunStatus::kUnreadable:
      ++counts.unfinished;
      break;
  }
}

}  // namespace

std::string MetricSpecLabel(const RunRecord& run, const std::string& metric) {
  const json* details = Find(run.metric_details, metric.c_str());
  const json* specification = details ? Find(*details, "specification") : nullptr;
  const json* evaluation = Find(run.run_spec, "evaluation");
  if (metric.starts_with("ape_")) {
    if (const json* align = specification ? Find(*specification, "alignment") : nullptr) {
      return "alignment " + JsonScalarText(*align);
    }
    if (const json* align = evaluation ? Find(*evaluation, "align") : nullptr) return "alignment " + JsonScalarText(*align);
    return "alignment unstated";
  }
  if (metric.starts_with("rpe_")) {
    const json* delta = specification ? Find(*specification, "delta") : nullptr;
    const json* delta_unit = specification ? Find(*specification, "delta_unit") : nullptr;
    if (delta && delta_unit) return "delta " + JsonScalarText(*delta) + " " + JsonScalarText(*delta_unit);
    if (const json* delta_m = evaluation ? Find(*evaluation, "rpe_delta_m") : nullptr) {
      return "delta " + JsonScalarText(*delta_m) + " m";
    }
    return "delta unstated";
  }
  return {};
}

SweepModel BuildSweepModel(std::vector<RunRecord> runs) {
  SweepModel model;
  std::sort(runs.begin(), runs.end(), [](const RunRecord& a, const RunRecord& b) { return a.run_id < b.run_id; });
  model.runs = std::move(runs);
  std::map<std::string, std::map<std::string, std::vector<std::size_t>>> by_sequence;
  std::set<std::string> algorithms;
  for (std::size_t i = 0; i < model.runs.size(); ++i) {
    const RunRecord& run = model.runs[i];
    by_sequence[run.sequence][run.algorithm].push_back(i);
    algorithms.insert(run.algorithm);
    Count(run, model.counts);
  }
  model.algorithms.assign(algorithms.begin(), algorithms.end());
  for (auto& [sequence_name, by_algorithm] : by_sequence) {
    SequenceModel sequence;
    sequence.name = sequence_name;
    std::vector<std::size_t> all;
    for (auto& [algorithm, indices] : by_algorithm) {
      std::stable_sort(indices.begin(), indices.end(), [&](std::size_t a, std::size_t b) {
        return model.runs[a].iteration < model.runs[b].iteration;
      });
      all.insert(all.end(), indices.begin(), indices.end());
    }
    sequence.trajectory_columns = BuildColumns(model.runs, all, kTrajectoryCandidates);
    sequence.map_columns = BuildColumns(model.runs, all, kMapCandidates);
    sequence.has_reference = !sequence.trajectory_columns.empty();
    for (auto& [algorithm, indices] : by_algorithm) {
      AlgorithmRow row;
      row.algorithm = algorithm;
      row.runs = indices;
      for (std::size_t index : indices) Count(model.runs[index], row.counts);
      for (const MetricColumn& column : sequence.trajectory_columns) {
        row.trajectory_cells.push_back(BuildCell(model.runs, indices, column));
      }
      for (const MetricColumn& column : sequence.map_columns) {
        row.map_cells.push_back(BuildCell(model.runs, indices, column));
      }
      ChooseMedianRun(model.runs, row);
      sequence.rows.push_back(std::move(row));
    }
    MarkBest(sequence.rows, &AlgorithmRow::trajectory_cells, sequence.trajectory_columns.size());
    MarkBest(sequence.rows, &AlgorithmRow::map_cells, sequence.map_columns.size());
    model.sequences.push_back(std::move(sequence));
  }
  return model;
}

}  // namespace slamsweep::report
