#include "report/html/text_outputs.h"

#include <set>

#include "report/html/number_format.h"

namespace slamsweep::report::inline html {

namespace {

std::string Number(const std::optional<double>& value) {
  if (!value) return "";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", *value);
  return buffer;
}

std::string CellText(const std::string& name, const MetricColumn& column, const MetricCell& cell) {
  std::string out = "metric: " + column.metric + " " + column.statistic + " (" + column.title + ")\n";
  if (!column.spec.empty()) out += "specification: " + column.spec + "\n";
  if (!column.unit.empty()) out += "unit: " + column.unit + "\n";
  out += "n: " + std::to_string(cell.summary.n) + "\n";
  out += name + "_mean: " + (cell.summary.n > 0 ? Number(cell.summary.mean) : "n/a") + "\n";
  out += name + "_std: " + (cell.summary.std ? Number(*cell.summary.std) : "n/a") + "\n";
  return out;
}

std::string Header(const SequenceModel& sequence, const AlgorithmRow& row) {
  return "algorithm: " + row.name + "\nparameters: " + (row.parameters.empty() ? "-" : row.parameters) +
         "\nsequence: " + sequence.name + "\nnoise: " + sequence.noise +
         (row.flags.empty() ? "" : "\nflags: " + orchestrator::RunFlagsLabel(row.flags)) +
         "\nruns: " + std::to_string(row.counts.total) + "\nok: " + std::to_string(row.counts.ok) +
         "\nfailed: " + std::to_string(row.counts.failed) + "\n";
}

}  // namespace

std::string RmseText(const SequenceModel& sequence, const AlgorithmRow& row) {
  std::string out = Header(sequence, row);
  bool any = false;
  for (std::size_t c = 0; c < sequence.trajectory_columns.size(); ++c) {
    const MetricColumn& column = sequence.trajectory_columns[c];
    if (column.metric != "ape_trans" || column.statistic != "rmse") continue;
    out += CellText("rmse", column, row.trajectory_cells[c]);
    any = true;
  }
  if (!any) out += "rmse_mean: n/a\nrmse_std: n/a\nnote: no ATE for this sequence (no reference trajectory)\n";
  return out;
}

std::string MapMetricText(const SequenceModel& sequence, const AlgorithmRow& row, const std::string& metric) {
  std::string out = Header(sequence, row);
  for (std::size_t c = 0; c < sequence.map_columns.size(); ++c) {
    if (sequence.map_columns[c].metric == metric)
      return out + CellText(metric, sequence.map_columns[c], row.map_cells[c]);
  }
  return out + metric + "_mean: n/a\n" + metric + "_std: n/a\nnote: no run produced this metric\n";
}

}  // namespace slamsweep::report::inline html
