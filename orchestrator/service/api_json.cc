#include "orchestrator/service/api_json.h"

#include <string>

namespace slamsweep::orchestrator::service {

nlohmann::json SweepJson(const SweepView& view) {
  const QueuedSweep& sweep = view.sweep;
  const std::string base = "/api/sweeps/" + std::to_string(sweep.id);
  nlohmann::json json = {{"id", sweep.id},
                         {"name", sweep.name},
                         {"config", sweep.config_name},
                         {"state", std::string(ToString(sweep.state))},
                         {"cancel_requested", sweep.cancel_requested},
                         {"priority", sweep.priority},
                         {"submitter", sweep.submitter},
                         {"submitted_at", sweep.submitted_at},
                         {"started_at", sweep.started_at},
                         {"finished_at", sweep.finished_at},
                         {"result_dir", sweep.result_dir.string()},
                         {"message", sweep.message},
                         {"counts",
                          {{"total", view.counts.total},
                           {std::string(ToString(QueuedRunState::kQueued)), view.counts.queued},
                           {std::string(ToString(QueuedRunState::kRunning)), view.counts.running},
                           {std::string(ToString(QueuedRunState::kOk)), view.counts.ok},
                           {std::string(ToString(QueuedRunState::kFailed)), view.counts.failed},
                           {std::string(ToString(QueuedRunState::kReused)), view.counts.reused},
                           {std::string(ToString(QueuedRunState::kCancelled)), view.counts.cancelled},
                           {"finished", view.counts.finished()}}},
                         {"eta", view.eta},
                         {"report", std::string(ToString(view.report))},
                         {"links",
                          {{"self", base},
                           {"runs", base + "/runs"},
                           {"cancel", base + "/cancel"},
                           {"page", "/sweeps/" + std::to_string(sweep.id)}}}};
  if (IsFinished(sweep.state)) {
    json["links"]["junit"] = base + "/junit.xml";
    json["links"]["summary_json"] = base + "/summary.json";
    json["links"]["summary_csv"] = base + "/summary.csv";
  }
  if (view.report == ReportState::kReady) {
    json["links"]["report"] = "/sweeps/" + std::to_string(sweep.id) + "/report/index.html";
    json["links"]["report_files"] = base + "/report";
  }
  return json;
}

nlohmann::json RunJson(const RunView& run) {
  return {{"run_id", run.run_id},
          {"state", std::string(ToString(run.state))},
          {"attempt", run.attempt},
          {"reused_from", run.reused_from ? nlohmann::json(*run.reused_from) : nlohmann::json(nullptr)},
          {"wall_s", run.wall_s ? nlohmann::json(*run.wall_s) : nlohmann::json(nullptr)},
          {"reason", run.reason}};
}

nlohmann::json ErrorJson(const std::string& message) { return {{"error", message}}; }

}  // namespace slamsweep::orchestrator::service
