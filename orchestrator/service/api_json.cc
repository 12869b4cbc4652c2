#include "orchestrator/service/api_json.h"

#include <string>

namespace slamsweep::orchestrator::service {

nlohmann::json SweepJson(const SweepView& view) {
  const QueuedSweep& sweep = view.sweep;
  const std::string base = "/api/sweeps/" + std::to_string(sweep.id);
  const bool finished = sweep.state == "ok" || sweep.state == "failed" || sweep.state == "cancelled";
  nlohmann::json json = {{"id", sweep.id},
                         {"name", sweep.name},
                         {"config", sweep.config_name},
                         {"state", sweep.state},
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
                           {"queued", view.counts.queued},
                           {"running", view.counts.running},
                           {"ok", view.counts.ok},
                           {"failed", view.counts.failed},
                           {"reused", view.counts.reused},
                           {"cancelled", view.counts.cancelled},
                           {"finished", view.counts.finished()}}},
                         {"eta", view.eta},
                         {"report", view.report},
                         {"links",
                          {{"self", base},
                           {"runs", base + "/runs"},
                           {"cancel", base + "/cancel"},
                           {"page", "/sweeps/" + std::to_string(sweep.id)}}}};
  if (finished) {
    json["links"]["junit"] = base + "/junit.xml";
    json["links"]["summary_json"] = base + "/summary.json";
    json["links"]["summary_csv"] = base + "/summary.csv";
  }
  if (view.report == "ready") {
    json["links"]["report"] = "/sweeps/" + std::to_string(sweep.id) + "/report/index.html";
    json["links"]["report_files"] = base + "/report";
  }
  return json;
}

nlohmann::json RunJson(const RunView& run) {
  return {{"run_id", run.run_id},
          {"state", run.state},
          {"attempt", run.attempt},
          {"reused_from", run.reused_from ? nlohmann::json(*run.reused_from) : nlohmann::json(nullptr)},
          {"wall_s", run.wall_s ? nlohmann::json(*run.wall_s) : nlohmann::json(nullptr)},
          {"reason", run.reason}};
}

nlohmann::json ErrorJson(const std::string& message) { return {{"error", message}}; }

}  // namespace slamsweep::orchestrator::service
