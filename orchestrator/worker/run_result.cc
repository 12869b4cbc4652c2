#include "orchestrator/worker/run_result.h"

#include <chrono>
#include <ctime>
#include <stdexcept>
#include <utility>

#include "orchestrator/files/atomic_file.h"
#include "orchestrator/run/run_status.h"

namespace slamsweep::orchestrator::inline worker {

void RunResult::Fail(FailureKind kind, std::string why) {
  if (failure_kind) return;
  failure_kind = kind;
  reason = std::move(why);
}

nlohmann::json ToJson(const RunResult& result) {
  nlohmann::json json;
  json["run_id"] = result.run_id;
  json["status"] = RunStatusName(result.ok() ? RunStatus::kOk : RunStatus::kFailed);
  json["failure_kind"] =
      result.failure_kind ? nlohmann::json(std::string(FailureKindName(*result.failure_kind))) : nlohmann::json();
  json["reason"] = result.reason;
  json["exit_code"] = result.exit_code ? nlohmann::json(*result.exit_code) : nlohmann::json();
  json["signal"] = result.signal ? nlohmann::json(*result.signal) : nlohmann::json();
  json["wall_s"] = result.wall_s;
  json["cpu_s"] = result.cpu_s;
  json["peak_rss_kb"] = result.peak_rss_kb ? nlohmann::json(*result.peak_rss_kb) : nlohmann::json();
  json["started_at"] = result.started_at;
  json["finished_at"] = result.finished_at;
  json["command"] = result.command;
  json["outputs"] = result.outputs;
  nlohmann::json metrics = nlohmann::json::array();
  for (const FlatMetric& metric : result.metrics.metrics) metrics.push_back(ToJson(metric));
  json["metrics"] = std::move(metrics);
  json["metric_details"] = result.metrics.details;
  if (!result.metrics.reference_floor.empty()) {
    nlohmann::json floor_metrics = nlohmann::json::array();
    for (const FlatMetric& metric : result.metrics.reference_floor) floor_metrics.push_back(ToJson(metric));
    json["reference_floor"] = {{"trajectory", "reference"},
                               {"metrics", std::move(floor_metrics)},
                               {"relations", result.metrics.reference_floor_details}};
  }
  std::vector<std::string> warnings = result.warnings;
  warnings.insert(warnings.end(), result.metrics.warnings.begin(), result.metrics.warnings.end());
  json["warnings"] = std::move(warnings);
  json["noise"] = result.noise;
  json["sequence"] = result.sequence;
  json["odometry_is_reference"] =
      result.odometry_is_reference ? nlohmann::json(*result.odometry_is_reference) : nlohmann::json();
  json["sandbox"] = result.sandbox;
  json["flags"] = ToJson(result.flags);
  return json;
}

std::string Iso8601Utc(std::int64_t seconds_since_epoch) {
  const std::time_t time = static_cast<std::time_t>(seconds_since_epoch);
  std::tm utc{};
  gmtime_r(&time, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string NowIso8601Utc() {
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return Iso8601Utc(std::chrono::duration_cast<std::chrono::seconds>(now).count());
}

void WriteJsonFileAtomically(const std::filesystem::path& file, const nlohmann::json& value) {
  // Compact: a run's record is read by programs (jq shows it to people), and indentation would be a third of it.
  WriteFileAtomically(file, value.dump() + "\n");
}

}  // namespace slamsweep::orchestrator::inline worker
