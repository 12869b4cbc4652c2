#include "report/model/sweep_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <map>
#include <set>
#include <tuple>

#include "orchestrator/run/run_json.h"

#include "orchestrator/store/validity_table.h"
#include "report/model/table_density.h"
#include "report/model/validity_support.h"

namespace slamsweep::report::inline model {

namespace {

using nlohmann::json;

struct ColumnCandidate {
  const char* metric;
  const char* statistic;
  const char* title;
};

// The relations metric of Kuemmerle et al. leads where a sequence has relations: on the Radish and
// Freiburg logs it is the only score against something other than one SLAM program's output. Then
// Table I of the paper (trajectory RMSE) and RPE.
constexpr ColumnCandidate kTrajectoryCandidates[] = {
    {"relations_trans", "mean", "Relations translation mean"},
    {"relations_rot", "mean", "Relations rotation mean"},
    {"ape_trans", "rmse", "ATE translation RMSE"},
    {"ape_rot", "rmse", "ATE rotation RMSE"},
    {"rpe_trans", "rmse", "RPE translation RMSE"},
    {"rpe_rot", "rmse", "RPE rotation RMSE"},
};

/// What ATE and RPE measure on a sequence whose reference is a corrected log.
constexpr const char* kCorrectedLogAgreement = "agreement with the corrected log (GMapping's output)";

// The three ground-truth-free metrics (paper sections III.A-C).
constexpr ColumnCandidate kMapCandidates[] = {
    {"occupied_to_free_unknown", "value", "Occupied proportion (occupied / free+unknown)"},
    {"corners", "value", "Corners"},
    {"enclosed_areas", "value", "Enclosed areas"},
    // Beyond the paper, where the sequence has a reference (evaluator/map_compare/README.md).
    {"map_chamfer", "value", "Map vs reference: Chamfer distance"},
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
      columns.push_back({candidate.metric, candidate.statistic, candidate.title, unit, std::move(spec), {}});
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

std::string AdapterOf(const RunRecord& run) {
  const auto algorithm = run.run_spec.find("algorithm");
  if (algorithm == run.run_spec.end() || !algorithm->is_object()) return {};
  const auto adapter = algorithm->find("adapter");
  return adapter != algorithm->end() && adapter->is_string() ? adapter->get<std::string>() : std::string();
}

void MarkBest(std::vector<AlgorithmRow>& rows, const std::vector<MetricColumn>& columns,
              std::vector<MetricCell> AlgorithmRow::*cells) {
  for (std::size_t c = 0; c < columns.size(); ++c) {
    double best = std::numeric_limits<double>::infinity();
    for (const AlgorithmRow& row : rows) {
      const MetricCell& cell = (row.*cells)[c];
      if (IsBestCandidate(row, columns[c], cell)) best = std::min(best, cell.summary.mean);
    }
    for (AlgorithmRow& row : rows) {
      MetricCell& cell = (row.*cells)[c];
      cell.best = IsBestCandidate(row, columns[c], cell) && cell.summary.mean == best;
    }
  }
}

/// A ground-truth-free map metric names a best run only where the validity study supports it.
void WithholdUnsupportedBest(SequenceModel& sequence, const SweepModel& model, const SweepModelOptions& options) {
  for (MetricColumn& column : sequence.map_columns) {
    const std::string key = column.metric + "." + column.statistic;
    const evaluator::ValidityQuantity* quantity = evaluator::FindValidityQuantity(key);
    if (!quantity || quantity->kind != std::string_view("paper map metric")) continue;  // a real error
    const ValiditySupport support =
        SupportFor(key, sequence.name, model.validity, options.named_study ? &*options.named_study : nullptr,
                   options.named_study_source);
    if (!support.supported) column.best_withheld = support.reason;
  }
}

/// Per algorithm name, the parameter names whose values are not the same in all its runs: what a
/// row's label must show to tell its rows apart.
std::map<std::string, std::set<std::string>> VaryingParameters(const std::vector<RunRecord>& runs) {
  std::map<std::string, std::vector<const json*>> by_algorithm;
  for (const RunRecord& run : runs) by_algorithm[run.algorithm].push_back(&run.parameter_values);
  std::map<std::string, std::set<std::string>> varying;
  for (const auto& [algorithm, values] : by_algorithm) {
    std::set<std::string> names;
    for (const json* parameters : values) {
      for (const auto& [name, value] : parameters->items()) names.insert(name);
    }
    for (const std::string& name : names) {
      const json* first = values.front()->contains(name) ? &values.front()->at(name) : nullptr;
      for (const json* parameters : values) {
        const json* value = parameters->contains(name) ? &parameters->at(name) : nullptr;
        if ((first == nullptr) != (value == nullptr) || (first != nullptr && *first != *value)) {
          varying[algorithm].insert(name);
          break;
        }
      }
    }
  }
  return varying;
}

std::string RowLabel(const RunRecord& run, const std::set<std::string>& varying) {
  std::string shown;
  for (const auto& [name, value] : run.parameter_values.items()) {
    if (varying.count(name) == 0) continue;
    if (!shown.empty()) shown += ';';
    shown += name + "=" + (value.is_string() ? value.get<std::string>() : value.dump());
  }
  return shown.empty() ? run.algorithm : run.algorithm + " [" + shown + "]";
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

/// Whether the run's reference is a corrected log (run.json's sequence ground_truth corrected_poses).
bool ReferenceIsCorrectedLog(const RunRecord& run) {
  const json* sequence = Find(run.run_spec, "sequence");
  const json* ground_truth = sequence ? Find(*sequence, "ground_truth") : nullptr;
  return ground_truth && ground_truth->is_string() && ground_truth->get<std::string>() == "corrected_poses";
}

/// The reference floor of a table: the reference itself scored by the relations metric as the runs
/// were (result.json's reference_floor of the first successful run that has one; every run of a
/// table scores the same reference against the same relations, with its own odometry between poses,
/// which is the same robot odometry unless noise was drawn). Absent without relations.
std::optional<AlgorithmRow> ReferenceFloorRow(const std::vector<RunRecord>& runs, const std::vector<std::size_t>& all,
                                              const SequenceModel& sequence) {
  for (std::size_t index : all) {
    const RunRecord& run = runs[index];
    if (run.status != RunStatus::kOk || run.reference_floor.empty()) continue;
    AlgorithmRow row;
    row.kind = RowKind::kReferenceFloor;
    row.name = "reference floor";
    row.algorithm = ReferenceIsCorrectedLog(run) ? "reference floor: the corrected log itself" : "reference floor";
    for (const MetricColumn& column : sequence.trajectory_columns) {
      MetricCell cell;
      for (const FlatMetric& metric : run.reference_floor) {
        if (metric.metric == column.metric && metric.statistic == column.statistic && metric.value) {
          cell.values.push_back(*metric.value);
        }
      }
      cell.summary = ComputeMeanStd(cell.values);
      row.trajectory_cells.push_back(std::move(cell));
    }
    row.map_cells.resize(sequence.map_columns.size());
    return row;
  }
  return std::nullopt;
}

/// The published rows of a table: figures for the log whose relations file the table's runs were scored
/// against, unless the runs were cut with max_scans. A figure fills the relations columns it has
/// (translation in m, rotation in deg); its std is the published spread over the relations, not over runs.
/// Where the table's log holds part of the run (relations outside the log), the row says that the figure
/// is over the whole log's relations, not the table's.
std::vector<AlgorithmRow> PublishedRows(const std::vector<RunRecord>& runs, const std::vector<std::size_t>& all,
                                        const SequenceModel& sequence, const std::vector<PublishedFigure>& published) {
  std::string log;
  for (std::size_t index : all) {
    const json* spec = Find(runs[index].run_spec, "sequence");
    const json* relations = spec ? Find(*spec, "relations") : nullptr;
    const json* max_scans = spec ? Find(*spec, "max_scans") : nullptr;
    if (relations == nullptr || !relations->is_string() || (max_scans != nullptr && !max_scans->is_null())) continue;
    log = std::filesystem::path(relations->get<std::string>()).stem().string();
    break;
  }
  std::vector<AlgorithmRow> rows;
  if (log.empty()) return rows;
  for (const PublishedFigure& figure : published) {
    if (figure.sequence != log) continue;
    AlgorithmRow row;
    row.kind = RowKind::kPublished;
    row.name = "published: " + figure.label;
    row.algorithm = "published: " + figure.label + " [" + figure.source + (figure.verified ? "" : ", unverified") + "]";
    row.parameters = figure.citation;
    if (sequence.relations_inside_log && sequence.relations_outside_log > 0) {
      row.scope_note = fmt::format(
          "over the whole log's relations, not the same relations: this table scores the {} of {} that lie inside "
          "its log",
          *sequence.relations_inside_log, *sequence.relations_inside_log + sequence.relations_outside_log);
    }
    bool any = false;
    for (const MetricColumn& column : sequence.trajectory_columns) {
      MetricCell cell;
      const auto& value =
          column.metric == "relations_trans" && column.statistic == "mean" && column.unit == "m"   ? figure.trans_abs
          : column.metric == "relations_rot" && column.statistic == "mean" && column.unit == "deg" ? figure.rot_abs
                                                                                                   : std::nullopt;
      if (value) {
        cell.values = {value->first};
        cell.summary = ComputeMeanStd(cell.values);
        cell.summary.std = value->second;
        any = true;
      }
      row.trajectory_cells.push_back(std::move(cell));
    }
    row.map_cells.resize(sequence.map_columns.size());
    if (any) rows.push_back(std::move(row));
  }
  return rows;
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

bool IsBestCandidate(const AlgorithmRow& row) {
  return row.kind == RowKind::kContestant && row.flags.empty() && !row.odometry_is_reference && row.counts.total > 0 &&
         row.counts.ok == row.counts.total;
}

bool IsBestCandidate(const AlgorithmRow& row, const MetricColumn& column, const MetricCell& cell) {
  return IsBestCandidate(row) && column.best_withheld.empty() && cell.summary.n > 0 &&
         cell.summary.n == row.counts.total;
}

std::string MetricSpecLabel(const RunRecord& run, const std::string& metric) {
  const json* details = Find(run.metric_details, metric.c_str());
  const json* specification = details ? Find(*details, "specification") : nullptr;
  const json* evaluation = Find(run.run_spec, "evaluation");
  if (metric.starts_with("ape_")) {
    if (const json* align = specification ? Find(*specification, "alignment") : nullptr) {
      return "alignment " + JsonScalarText(*align);
    }
    if (const json* align = evaluation ? Find(*evaluation, "align") : nullptr)
      return "alignment " + JsonScalarText(*align);
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

namespace {

std::optional<double> FlatValue(const RunRecord& run, std::string_view metric, std::string_view statistic) {
  for (const FlatMetric& flat : run.metrics) {
    if (flat.metric == metric && flat.statistic == statistic) return flat.value;
  }
  return std::nullopt;
}

/// The table's relations, inside and outside the log, from its first run that scored them (every run of a
/// table reads the same sequence and cut).
void CountRelations(const std::vector<RunRecord>& runs, const std::vector<std::size_t>& indices,
                    SequenceModel& sequence) {
  for (std::size_t index : indices) {
    const std::optional<double> used = FlatValue(runs[index], "relations_trans", "n");
    const std::optional<double> not_covered = FlatValue(runs[index], "relations_trans", "not_covered");
    if (!used || !not_covered) continue;
    sequence.relations_inside_log = static_cast<std::size_t>(*used + *not_covered);
    sequence.relations_outside_log =
        static_cast<std::size_t>(FlatValue(runs[index], "relations_trans", "outside_log").value_or(0.0));
    return;
  }
}

}  // namespace

SweepModel BuildSweepModel(std::vector<RunRecord> runs, const SweepModelOptions& options) {
  SweepModel model;
  std::sort(runs.begin(), runs.end(), [](const RunRecord& a, const RunRecord& b) { return a.run_id < b.run_id; });
  model.runs = std::move(runs);
  {
    std::vector<evaluator::ValidityRun> validity_runs = orchestrator::ToValidityRuns(model.runs);
    std::optional<evaluator::ValidityStudy> stored;
    if (options.stored_validity) stored = orchestrator::StoredValidityStudyFor(*options.stored_validity, validity_runs);
    model.validity = stored ? std::move(*stored) : evaluator::ComputeValidityStudy(std::move(validity_runs));
  }
  // Table (sequence, noise) -> row (algorithm name, parameters) -> runs.
  using RowKey =
      std::tuple<std::string, std::string, std::string, std::string>;  // algorithm, parameters, odometry, build
  std::map<std::pair<std::string, std::string>, std::map<RowKey, std::vector<std::size_t>>> tables;
  std::set<std::string> algorithms;
  std::set<std::string> sweep_names;
  for (std::size_t i = 0; i < model.runs.size(); ++i) {
    const RunRecord& run = model.runs[i];
    tables[{run.sequence, run.noise}]
          [{run.algorithm, run.parameters, run.odometry, orchestrator::BuildSignatureOfRunJson(run.run_spec)}]
              .push_back(i);
    algorithms.insert(run.algorithm);
    if (!run.sweep.empty()) sweep_names.insert(run.sweep);
    Count(run, model.counts);
  }
  model.algorithms.assign(algorithms.begin(), algorithms.end());
  for (const std::string& name : sweep_names) model.sweep_name += (model.sweep_name.empty() ? "" : ", ") + name;
  const std::map<std::string, std::set<std::string>> varying = VaryingParameters(model.runs);
  static const std::set<std::string> kNone;
  for (auto& [table_key, rows] : tables) {
    SequenceModel sequence;
    sequence.name = table_key.first;
    sequence.noise = table_key.second;
    sequence.key = sequence.name + "/" + sequence.noise;
    sequence.title = sequence.noise.empty() ? sequence.name : sequence.name + ", noise " + sequence.noise;
    std::vector<std::size_t> all;
    for (auto& [row_key, indices] : rows) {
      std::stable_sort(indices.begin(), indices.end(),
                       [&](std::size_t a, std::size_t b) { return model.runs[a].iteration < model.runs[b].iteration; });
      all.insert(all.end(), indices.begin(), indices.end());
    }
    sequence.trajectory_columns = BuildColumns(model.runs, all, kTrajectoryCandidates);
    if (std::any_of(all.begin(), all.end(), [&](std::size_t i) { return ReferenceIsCorrectedLog(model.runs[i]); })) {
      for (MetricColumn& column : sequence.trajectory_columns) {
        if (column.metric.starts_with("ape_") || column.metric.starts_with("rpe_")) {
          column.title += ": " + std::string(kCorrectedLogAgreement);
        }
      }
    }
    sequence.map_columns = BuildColumns(model.runs, all, kMapCandidates);
    sequence.has_reference = !sequence.trajectory_columns.empty();
    CountRelations(model.runs, all, sequence);
    sequence.scan_spacing = TableScanSpacing(model.runs, all);
    std::map<std::tuple<std::string, std::string, std::string>, std::size_t> builds_per_group;
    std::map<std::pair<std::string, std::string>, std::set<std::string>> modes_per_algorithm;
    for (const auto& [row_key, indices] : rows) {
      ++builds_per_group[{std::get<0>(row_key), std::get<1>(row_key), std::get<2>(row_key)}];
      modes_per_algorithm[{std::get<0>(row_key), std::get<1>(row_key)}].insert(std::get<2>(row_key));
    }
    for (auto& [row_key, indices] : rows) {
      const RunRecord& first = model.runs[indices.front()];
      const auto found = varying.find(first.algorithm);
      AlgorithmRow row;
      row.name = first.algorithm;
      row.parameters = first.parameters;
      row.algorithm = RowLabel(first, found == varying.end() ? kNone : found->second);
      if (modes_per_algorithm.at({std::get<0>(row_key), std::get<1>(row_key)}).size() > 1) {
        const std::string& mode = std::get<2>(row_key);
        row.algorithm += " [" + (mode.empty() ? std::string("unrecorded") : mode) + " odometry]";
      }
      row.build = std::get<3>(row_key);
      row.build_split = builds_per_group.at({std::get<0>(row_key), std::get<1>(row_key), std::get<2>(row_key)}) > 1;
      if (row.build_split) {
        row.algorithm += " [build " + (row.build.empty() ? std::string("unrecorded") : row.build) + "]";
        row.build_description = orchestrator::BuildDescriptionOfRunJson(first.run_spec);
      }
      row.seeding = first.seeding;
      row.runs = indices;
      if (AdapterOf(first) == "odometry") row.kind = RowKind::kOdometryBaseline;
      for (std::size_t index : indices) {
        const RunRecord& run = model.runs[index];
        Count(run, row.counts);
        row.odometry_is_reference = row.odometry_is_reference || run.odometry_is_reference;
        row.flags |= run.flags;
        if (run.seeding != row.seeding) row.seeding = "mixed";
      }
      for (const MetricColumn& column : sequence.trajectory_columns) {
        row.trajectory_cells.push_back(BuildCell(model.runs, indices, column));
      }
      for (const MetricColumn& column : sequence.map_columns) {
        row.map_cells.push_back(BuildCell(model.runs, indices, column));
      }
      ChooseMedianRun(model.runs, row);
      sequence.rows.push_back(std::move(row));
    }
    if (std::optional<AlgorithmRow> floor = ReferenceFloorRow(model.runs, all, sequence)) {
      sequence.rows.push_back(std::move(*floor));
    }
    for (AlgorithmRow& row : PublishedRows(model.runs, all, sequence, options.published)) {
      sequence.rows.push_back(std::move(row));
    }
    WithholdUnsupportedBest(sequence, model, options);
    MarkBest(sequence.rows, sequence.trajectory_columns, &AlgorithmRow::trajectory_cells);
    MarkBest(sequence.rows, sequence.map_columns, &AlgorithmRow::map_cells);
    model.sequences.push_back(std::move(sequence));
  }
  return model;
}

}  // namespace slamsweep::report::inline model
