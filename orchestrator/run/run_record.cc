#include "orchestrator/run/run_record.h"

namespace slamsweep::orchestrator::inline run {

std::optional<double> RunRecord::Metric(std::string_view metric_name, std::string_view statistic) const {
  for (const FlatMetric& m : metrics) {
    if (m.metric == metric_name && m.statistic == statistic) return m.value;
  }
  return std::nullopt;
}

std::string RunRecord::MetricUnit(std::string_view metric_name, std::string_view statistic) const {
  for (const FlatMetric& m : metrics) {
    if (m.metric == metric_name && m.statistic == statistic) return m.unit;
  }
  return {};
}

std::optional<double> ScanRateOfResult(const nlohmann::json& result) {
  const auto sequence = result.find("sequence");
  if (sequence == result.end() || !sequence->is_object()) return std::nullopt;
  const auto scans = sequence->find("scans");
  const auto span = sequence->find("span_s");
  if (scans == sequence->end() || span == sequence->end() || !scans->is_number() || !span->is_number()) {
    return std::nullopt;
  }
  const double seconds = span->get<double>();
  if (!(seconds > 0.0) || scans->get<double>() < 2.0) return std::nullopt;
  return (scans->get<double>() - 1.0) / seconds;
}

void ReadResultFields(const nlohmann::json& result, RunRecord& run) {
  using nlohmann::json;
  const auto text = [&](const char* key) {
    const auto found = result.find(key);
    return found != result.end() && found->is_string() ? found->get<std::string>() : std::string();
  };
  const auto number = [&](const char* key) -> std::optional<double> {
    const auto found = result.find(key);
    return found != result.end() && found->is_number() ? std::optional<double>(found->get<double>()) : std::nullopt;
  };
  const auto integer = [&](const char* key) -> std::optional<int> {
    const auto found = result.find(key);
    return found != result.end() && found->is_number_integer() ? std::optional<int>(found->get<int>()) : std::nullopt;
  };
  const auto strings = [&](const char* key) {
    std::vector<std::string> out;
    const auto found = result.find(key);
    if (found == result.end() || !found->is_array()) return out;
    for (const json& item : *found) {
      if (item.is_string()) out.push_back(item.get<std::string>());
    }
    return out;
  };
  run.failure_kind = text("failure_kind");
  run.reason = text("reason");
  run.exit_code = integer("exit_code");
  run.signal = integer("signal");
  run.wall_s = number("wall_s");
  run.cpu_s = number("cpu_s");
  run.peak_rss_kb = number("peak_rss_kb");
  run.started_at = text("started_at");
  run.finished_at = text("finished_at");
  run.command = strings("command");
  run.warnings = strings("warnings");
  run.scan_rate_hz = ScanRateOfResult(result);
}

}  // namespace slamsweep::orchestrator::inline run
