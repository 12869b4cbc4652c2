#include "report/model/segment_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <map>
#include <set>

#include "evaluator/formats/trajectory/segment_errors_csv.h"

namespace slamsweep::report::inline model {
namespace {

using nlohmann::json;

/// What one run's result.json says about its segment RPE.
struct RunSegments {
  std::vector<double> lengths_m;
  std::map<double, double> mean_drift_pct;
  std::map<double, double> mean_rotation_deg_per_m;
  std::string lengths_from;
  std::optional<double> reference_path_m;
};

std::optional<double> NumberAt(const json& object, const json::json_pointer& pointer) {
  if (!object.contains(pointer) || !object.at(pointer).is_number()) return std::nullopt;
  return object.at(pointer).get<double>();
}

std::optional<RunSegments> ReadRunSegments(const RunRecord& run) {
  const auto found = run.metric_details.find("segment_rpe");
  if (run.status != RunStatus::kOk || found == run.metric_details.end() || !found->is_object()) return std::nullopt;
  const json& details = *found;
  const json::json_pointer lengths_pointer("/specification/lengths_m");
  if (!details.contains(lengths_pointer) || !details.at(lengths_pointer).is_array()) return std::nullopt;
  RunSegments segments;
  for (const json& length : details.at(lengths_pointer)) {
    if (length.is_number()) segments.lengths_m.push_back(length.get<double>());
  }
  std::sort(segments.lengths_m.begin(), segments.lengths_m.end());
  if (const auto from = details.at("specification").find("lengths_from");
      from != details.at("specification").end() && from->is_string()) {
    segments.lengths_from = from->get<std::string>();
  }
  segments.reference_path_m = NumberAt(details, json::json_pointer("/specification/reference_path_m"));
  if (const auto lengths = details.find("lengths"); lengths != details.end() && lengths->is_array()) {
    for (const json& entry : *lengths) {
      const std::optional<double> length = NumberAt(entry, json::json_pointer("/length_m"));
      if (!length) continue;
      if (const auto drift = NumberAt(entry, json::json_pointer("/translation_pct/mean"))) {
        segments.mean_drift_pct[*length] = *drift;
      }
      if (const auto rotation = NumberAt(entry, json::json_pointer("/rotation_deg_per_m/mean"))) {
        segments.mean_rotation_deg_per_m[*length] = *rotation;
      }
    }
  }
  return segments;
}

std::string LengthsFrom(const std::vector<RunSegments>& runs) {
  std::set<std::string> sources;
  std::optional<double> path;
  for (const RunSegments& run : runs) {
    sources.insert(run.lengths_from);
    if (run.reference_path_m) path = run.reference_path_m;
  }
  if (sources.size() != 1) return "chosen differently by different runs (see the notes)";
  if (*sources.begin() == "reference path") {
    return "10, 20, 30, 40 and 50 % of the reference path" + (path ? fmt::format(" ({:.1f} m)", *path) : "") +
           ", rounded to 1 m (as KITTI and rpg_trajectory_evaluation do)";
  }
  if (*sources.begin() == "evaluation.rpe_segments_m") return "as configured (evaluation.rpe_segments_m)";
  return "as recorded by the runs";
}

}  // namespace

std::optional<SegmentTable> BuildSegmentTable(const SweepModel& model, const SequenceModel& sequence) {
  SegmentTable table;
  table.table_key = sequence.key;
  std::vector<RunSegments> all_runs;
  std::set<double> lengths;
  std::set<std::vector<double>> length_sets;
  struct RowRuns {
    std::vector<std::pair<const RunRecord*, RunSegments>> runs;
  };
  std::vector<RowRuns> per_row(sequence.rows.size());
  for (std::size_t r = 0; r < sequence.rows.size(); ++r) {
    for (const std::size_t index : sequence.rows[r].runs) {
      const RunRecord& run = model.runs[index];
      std::optional<RunSegments> segments = ReadRunSegments(run);
      if (!segments) continue;
      lengths.insert(segments->lengths_m.begin(), segments->lengths_m.end());
      length_sets.insert(segments->lengths_m);
      all_runs.push_back(*segments);
      per_row[r].runs.emplace_back(&run, std::move(*segments));
    }
  }
  if (all_runs.empty()) return std::nullopt;
  table.lengths_m.assign(lengths.begin(), lengths.end());
  table.lengths_from = LengthsFrom(all_runs);
  if (length_sets.size() > 1) {
    table.notes.push_back(
        "The runs of this table were scored at different sets of segment lengths (their sweeps had "
        "different evaluation.rpe_segments_m): each length pools only the runs scored at it, and a row "
        "with fewer runs at a length says so.");
  }

  for (std::size_t r = 0; r < sequence.rows.size(); ++r) {
    if (per_row[r].runs.empty()) continue;
    SegmentRow row;
    row.row = r;
    std::vector<std::vector<double>> translation_m(table.lengths_m.size());
    std::vector<std::vector<double>> translation_pct(table.lengths_m.size());
    std::vector<std::vector<double>> rotation(table.lengths_m.size());
    std::vector<std::vector<double>> run_drift(table.lengths_m.size());
    std::vector<std::vector<double>> run_rotation(table.lengths_m.size());
    std::set<std::vector<double>> row_sets;
    for (const auto& [run, segments] : per_row[r].runs) {
      row_sets.insert(segments.lengths_m);
      for (std::size_t k = 0; k < table.lengths_m.size(); ++k) {
        const double length = table.lengths_m[k];
        if (const auto drift = segments.mean_drift_pct.find(length); drift != segments.mean_drift_pct.end()) {
          run_drift[k].push_back(drift->second);
        }
        if (const auto turn = segments.mean_rotation_deg_per_m.find(length);
            turn != segments.mean_rotation_deg_per_m.end()) {
          run_rotation[k].push_back(turn->second);
        }
      }
      std::vector<evaluator::SegmentErrorRecord> records;
      try {
        records = evaluator::ReadSegmentErrorsCsv(run->dir / "rpe_segments.csv");
      } catch (const std::exception& error) {
        row.notes.push_back("run " + run->run_id + ": its segments are not in the boxes (" + error.what() + ")");
        continue;
      }
      for (const evaluator::SegmentErrorRecord& record : records) {
        const auto at = std::find(table.lengths_m.begin(), table.lengths_m.end(), record.length_m);
        const bool listed = std::find(segments.lengths_m.begin(), segments.lengths_m.end(), record.length_m) !=
                            segments.lengths_m.end();
        if (at == table.lengths_m.end() || !listed) continue;
        const std::size_t k = static_cast<std::size_t>(at - table.lengths_m.begin());
        translation_m[k].push_back(record.translation_m);
        translation_pct[k].push_back(record.translation_pct);
        rotation[k].push_back(record.rotation_deg_per_m);
      }
    }
    if (row_sets.size() > 1) {
      row.notes.push_back(
          "runs of this row were scored at different segment lengths; each length pools only the "
          "runs scored at it");
    }
    for (std::size_t k = 0; k < table.lengths_m.size(); ++k) {
      SegmentCell cell;
      cell.translation_m = SummarizeBox(std::move(translation_m[k]));
      cell.translation_pct = SummarizeBox(std::move(translation_pct[k]));
      cell.rotation_deg_per_m = SummarizeBox(std::move(rotation[k]));
      cell.mean_drift_pct = ComputeMeanStd(run_drift[k]);
      cell.mean_rotation_deg_per_m = ComputeMeanStd(run_rotation[k]);
      row.cells.push_back(std::move(cell));
    }
    table.rows.push_back(std::move(row));
  }

  // Best: per length, the lowest mean drift among the rows IsBestCandidate admits, each with a drift
  // from every one of its runs (a drift is a real error: no validity study is needed).
  const auto candidate = [&](const SegmentRow& row, std::size_t k) {
    const AlgorithmRow& algorithm_row = sequence.rows[row.row];
    const std::size_t n = row.cells[k].mean_drift_pct.n;
    return IsBestCandidate(algorithm_row) && n > 0 && n == algorithm_row.counts.total;
  };
  for (std::size_t k = 0; k < table.lengths_m.size(); ++k) {
    double best = std::numeric_limits<double>::infinity();
    for (const SegmentRow& row : table.rows) {
      if (candidate(row, k)) best = std::min(best, row.cells[k].mean_drift_pct.mean);
    }
    for (SegmentRow& row : table.rows)
      row.cells[k].best = candidate(row, k) && row.cells[k].mean_drift_pct.mean == best;
  }
  return table;
}

}  // namespace slamsweep::report::inline model
