#include "report/model/load_runs.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "evaluator/core/input_error.h"

namespace slamsweep::report::inline model {

namespace {

using evaluator::InputError;
using nlohmann::json;

json ReadJsonFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open");
  std::ostringstream content;
  content << in.rdbuf();
  try {
    return json::parse(content.str());
  } catch (const json::parse_error& error) {
    throw InputError(path.string() + ": expected JSON (" + error.what() + ")");
  }
}

[[noreturn]] void FieldError(const std::filesystem::path& file, std::string_view field, std::string_view expected) {
  throw InputError(file.string() + ": field '" + std::string(field) + "': expected " + std::string(expected));
}

// Optional fields: absent or null leave the default; a value of the wrong type is an error,
// because a silently ignored typo would show a wrong number in the report.
std::string OptionalString(const json& object, const char* key, const std::filesystem::path& file) {
  const auto it = object.find(key);
  if (it == object.end() || it->is_null()) return {};
  if (!it->is_string()) FieldError(file, key, "a string");
  return it->get<std::string>();
}

std::optional<double> OptionalNumber(const json& object, const char* key, const std::filesystem::path& file) {
  const auto it = object.find(key);
  if (it == object.end() || it->is_null()) return std::nullopt;
  if (!it->is_number()) FieldError(file, key, "a number");
  return it->get<double>();
}

std::optional<int> OptionalInteger(const json& object, const char* key, const std::filesystem::path& file) {
  const auto it = object.find(key);
  if (it == object.end() || it->is_null()) return std::nullopt;
  if (!it->is_number_integer()) FieldError(file, key, "an integer");
  return it->get<int>();
}

std::vector<std::string> OptionalStrings(const json& object, const char* key, const std::filesystem::path& file) {
  std::vector<std::string> out;
  const auto it = object.find(key);
  if (it == object.end() || it->is_null()) return out;
  if (!it->is_array()) FieldError(file, key, "an array of strings");
  for (const json& item : *it) {
    if (!item.is_string()) FieldError(file, key, "an array of strings");
    out.push_back(item.get<std::string>());
  }
  return out;
}

// RunRecord::metric_details: of each metric its specification and its top-level numbers and texts (pairs,
// n, rmse...); of segment_rpe also its lengths with their mean drift and rotation (report/model/segment_model).
json MetricDetailsTheReportReads(const json& details) {
  json kept = json::object();
  for (const auto& [metric, detail] : details.items()) {
    json& entry = kept[metric] = json::object();
    if (!detail.is_object()) continue;
    for (const auto& [key, value] : detail.items()) {
      if (key == "specification" || value.is_primitive()) entry[key] = value;
    }
    const auto lengths = detail.find("lengths");
    if (metric != "segment_rpe" || lengths == detail.end() || !lengths->is_array()) continue;
    json& kept_lengths = entry["lengths"] = json::array();
    for (const json& length : *lengths) {
      if (!length.is_object()) continue;
      json item = json::object();
      for (const char* key : {"length_m", "n"}) {
        if (const auto value = length.find(key); value != length.end()) item[key] = *value;
      }
      for (const char* key : {"translation_pct", "rotation_deg_per_m"}) {
        const auto statistics = length.find(key);
        if (statistics == length.end() || !statistics->is_object()) continue;
        if (const auto mean = statistics->find("mean"); mean != statistics->end()) item[key]["mean"] = *mean;
      }
      kept_lengths.push_back(std::move(item));
    }
  }
  return kept;
}

void ReadRunSpec(const std::filesystem::path& file, RunRecord& run) {
  run.run_spec = ReadJsonFile(file);
  if (!run.run_spec.is_object()) throw InputError(file.string() + ": expected a JSON object");
  const json& spec = run.run_spec;
  if (const auto it = spec.find("algorithm"); it != spec.end()) {
    if (!it->is_object()) FieldError(file, "algorithm", "an object");
    run.algorithm = OptionalString(*it, "name", file);
  }
  if (const auto it = spec.find("sequence"); it != spec.end()) {
    if (!it->is_object()) FieldError(file, "sequence", "an object");
    run.sequence = OptionalString(*it, "name", file);
  }
  if (const auto it = spec.find("noise"); it != spec.end()) {
    if (!it->is_object()) FieldError(file, "noise", "an object");
    run.noise = OptionalString(*it, "name", file);
  }
  if (const auto it = spec.find("algorithm"); it != spec.end()) {
    if (const auto parameters = it->find("parameters"); parameters != it->end() && parameters->is_object()) {
      run.parameter_values = *parameters;
    }
  }
  if (const auto it = spec.find("group"); it != spec.end()) {
    if (!it->is_object()) FieldError(file, "group", "an object");
    run.parameters = OptionalString(*it, "parameters", file);
    run.odometry = OptionalString(*it, "odometry", file);
  } else if (!run.parameter_values.empty()) {
    // A run recorded before run.json named its group: its parameters still set it apart.
    run.parameters = run.parameter_values.dump();
  }
  if (const auto it = spec.find("odometry_is_reference"); it != spec.end() && it->is_boolean()) {
    run.odometry_is_reference = it->get<bool>();
  }
  run.seeding = OptionalString(spec, "seeding", file);
  run.flags = orchestrator::RunFlagsOf(spec, nullptr);
  run.sweep = OptionalString(spec, "sweep", file);
  run.iteration = OptionalInteger(spec, "iteration", file).value_or(0);
}

/// An array of {metric, statistic, value, unit}; a metric without a value (null) could not be
/// computed and is left out.
std::vector<FlatMetric> FlatMetrics(const json& array, const std::string& name, const std::filesystem::path& file) {
  if (!array.is_array()) FieldError(file, name, "an array of {metric, statistic, value, unit}");
  std::vector<FlatMetric> metrics;
  for (std::size_t i = 0; i < array.size(); ++i) {
    const json& item = array[i];
    const std::string field = name + "[" + std::to_string(i) + "]";
    if (!item.is_object()) FieldError(file, field, "an object {metric, statistic, value, unit}");
    FlatMetric metric;
    metric.metric = OptionalString(item, "metric", file);
    metric.statistic = OptionalString(item, "statistic", file);
    metric.unit = OptionalString(item, "unit", file);
    const std::optional<double> value = OptionalNumber(item, "value", file);
    if (metric.metric.empty() || metric.statistic.empty()) FieldError(file, field, "non-empty metric and statistic");
    if (!value) continue;
    metric.value = *value;
    metrics.push_back(std::move(metric));
  }
  return metrics;
}

void ReadResult(const std::filesystem::path& file, RunRecord& run) {
  const json result = ReadJsonFile(file);
  if (!result.is_object()) throw InputError(file.string() + ": expected a JSON object");
  const std::optional<RunStatus> status = orchestrator::RecordedRunStatus(OptionalString(result, "status", file));
  if (!status) {
    FieldError(file, "status",
               "\"" + std::string(RunStatusName(RunStatus::kOk)) + "\" or \"" +
                   std::string(RunStatusName(RunStatus::kFailed)) + "\"");
  }
  run.status = *status;
  run.failure_kind = OptionalString(result, "failure_kind", file);
  run.reason = OptionalString(result, "reason", file);
  run.exit_code = OptionalInteger(result, "exit_code", file);
  run.signal = OptionalInteger(result, "signal", file);
  run.wall_s = OptionalNumber(result, "wall_s", file);
  run.cpu_s = OptionalNumber(result, "cpu_s", file);
  run.peak_rss_kb = OptionalNumber(result, "peak_rss_kb", file);
  run.started_at = OptionalString(result, "started_at", file);
  run.finished_at = OptionalString(result, "finished_at", file);
  run.command = OptionalStrings(result, "command", file);
  if (const auto it = result.find("odometry_is_reference"); it != result.end() && it->is_boolean()) {
    run.odometry_is_reference = it->get<bool>();
  }
  run.flags = orchestrator::RunFlagsOf(run.run_spec, result);
  run.warnings = OptionalStrings(result, "warnings", file);
  run.scan_rate_hz = orchestrator::ScanRateOfResult(result);
  if (const auto it = result.find("outputs"); it != result.end() && !it->is_null()) {
    if (!it->is_object()) FieldError(file, "outputs", "an object");
    run.outputs.map = OptionalString(*it, "map", file);
    run.outputs.trajectory = OptionalString(*it, "trajectory", file);
    run.outputs.reference = OptionalString(*it, "reference", file);
    run.outputs.vector_map = OptionalString(*it, "vector_map", file);
    run.outputs.log = OptionalString(*it, "log", file);
    run.outputs.stages = OptionalStrings(*it, "stages", file);
    run.outputs.stage_animation = OptionalString(*it, "stage_animation", file);
  }
  if (const auto it = result.find("metrics"); it != result.end() && !it->is_null()) {
    run.metrics = FlatMetrics(*it, "metrics", file);
  }
  if (const auto it = result.find("reference_floor"); it != result.end() && it->is_object()) {
    if (const auto floor = it->find("metrics"); floor != it->end() && !floor->is_null()) {
      run.reference_floor = FlatMetrics(*floor, "reference_floor.metrics", file);
    }
  }
  if (const auto it = result.find("metric_details"); it != result.end() && it->is_object()) {
    run.metric_details = MetricDetailsTheReportReads(*it);
  }
  if (const auto it = result.find("sequence"); it != result.end() && it->is_object()) {
    if (const auto spacing = it->find("scan_spacing"); spacing != it->end()) run.scan_spacing = *spacing;
  }
}

}  // namespace

RunRecord LoadRun(const std::filesystem::path& run_dir) {
  RunRecord run;
  run.dir = run_dir;
  run.run_id = run_dir.filename().string();
  try {
    ReadRunSpec(run_dir / "run.json", run);
    if (std::filesystem::exists(run_dir / "result.json")) {
      ReadResult(run_dir / "result.json", run);
    } else {
      run.status = RunStatus::kUnfinished;
      run.reason = "no result.json: the run was interrupted or has not finished";
    }
  } catch (const std::exception& error) {
    run.status = RunStatus::kUnreadable;
    run.reason = error.what();
  }
  if (run.algorithm.empty()) run.algorithm = "?";
  if (run.sequence.empty()) run.sequence = "?";
  return run;
}

std::vector<RunRecord> LoadRuns(const std::filesystem::path& result_dir) {
  std::error_code error;
  if (!std::filesystem::is_directory(result_dir, error)) {
    throw InputError(result_dir.string() + ": expected a sweep output directory (with runs/ and summary.json)");
  }
  const std::filesystem::path runs_dir = result_dir / "runs";
  if (!std::filesystem::is_directory(runs_dir, error)) {
    throw InputError(runs_dir.string() + ": missing; expected the runs/<run-id>/ folders of a sweep");
  }
  std::vector<std::filesystem::path> dirs;
  for (const auto& entry : std::filesystem::directory_iterator(runs_dir)) {
    if (entry.is_directory()) dirs.push_back(entry.path());
  }
  std::sort(dirs.begin(), dirs.end());
  std::vector<RunRecord> runs;
  runs.reserve(dirs.size());
  for (const auto& dir : dirs) runs.push_back(LoadRun(std::filesystem::absolute(dir)));
  return runs;
}

}  // namespace slamsweep::report::inline model
