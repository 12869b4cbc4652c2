#include "report/html/text_outputs.h"

#include <set>

#include "report/html/number_format.h"

namespace slamsweep::report {

namespace {

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

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
  return "algorithm: " + row.algorithm + "\nsequence: " + sequence.name + "\nruns: " +
         std::to_string(row.counts.total) + "\nok: " + std::to_string(row.counts.ok) +
         "\nfailed: " + std::to_string(row.counts.failed) + "\n";
}

}  // namespace

std::string SummaryCsv(const SweepModel& model) {
  std::set<std::string> metric_names;
  for (const RunRecord& run : model.runs) {
    for (const FlatMetric& metric : run.metrics) metric_names.insert(metric.metric + "." + metric.statistic);
  }
  std::string out = "run_id,algorithm,sequence,noise,iteration,status,failure_kind,reason,wall_s,cpu_s,peak_rss_kb";
  for (const std::string& name : metric_names) out.append(",").append(CsvField(name));
  out += "\n";
  for (const RunRecord& run : model.runs) {
    out += CsvField(run.run_id) + "," + CsvField(run.algorithm) + "," + CsvField(run.sequence) + "," +
           CsvField(run.noise) + "," + std::to_string(run.iteration) + "," + std::string(RunStatusName(run.status)) +
           "," + CsvField(run.failure_kind) + "," + CsvField(run.reason) + "," + Number(run.wall_s) + "," +
           Number(run.cpu_s) + "," + Number(run.peak_rss_kb);
    for (const std::string& name : metric_names) {
      const std::size_t dot = name.rfind('.');
      out.append(",").append(Number(run.Metric(name.substr(0, dot), name.substr(dot + 1))));
    }
    out += "\n";
  }
  return out;
}

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
    if (sequence.map_columns[c].metric == metric) return out + CellText(metric, sequence.map_columns[c], row.map_cells[c]);
  }
  return out + metric + "_mean: n/a\n" + metric + "_std: n/a\nnote: no run produced this metric\n";
}

}  // namespace slamsweep::report
