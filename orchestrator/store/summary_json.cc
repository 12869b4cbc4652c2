#include "orchestrator/store/summary_json.h"

#include "orchestrator/files/atomic_file.h"
#include "orchestrator/store/group_summary.h"
#include "orchestrator/store/json_lookup.h"
#include "orchestrator/store/validity_table.h"

namespace slamsweep::orchestrator::inline store {
namespace {

using nlohmann::json;

std::string TextOr(const json& value, const std::string& fallback) {
  return value.is_string() ? value.get<std::string>() : fallback;
}

/// What ATE and RPE measure against, by the sequence's ground_truth kind (run.json's spec).
std::string ReferenceMeaning(const json& spec) {
  const std::string kind = TextOr(Nested(spec, "sequence", "ground_truth"), "");
  if (kind == "corrected_poses") {
    return "corrected log: ATE and RPE are agreement with the corrected log (GMapping's output); the relations "
           "error is the score against independent truth";
  }
  if (kind == "exact") return "exact ground truth (simulated)";
  if (kind == "measured") {
    const std::string topic = TextOr(Nested(spec, "sequence", "reference_topic"), "");
    const std::string frame = TextOr(Nested(spec, "sequence", "reference_frame"), "");
    const std::string source = !topic.empty() ? "topic " + topic : !frame.empty() ? "tf frame " + frame : "the bag";
    return "measured: a reference recorded with the data (" + source +
           "); ATE and RPE are agreement with it, as good as the system that measured it";
  }
  if (kind == "relations_only") return "relations only";
  return "none";
}

}  // namespace

json SummarizeRun(const RunRecord& run) {
  const json& spec = run.run_spec;
  const json& result = run.result;
  json metrics = json::object();
  json units = json::object();
  for (const FlatMetric& m : run.metrics) {
    // JSON has no NaN: a statistic that is not a number stays null, as the worker wrote it.
    metrics[m.metric][m.statistic] = m.value.has_value() ? json(*m.value) : json(nullptr);
    if (!m.unit.empty()) units[m.metric] = m.unit;
  }
  const json& parameters = Nested(spec, "algorithm", "parameters");
  const json& outputs = FieldOrNull(result, "outputs");
  return json{
      {"run_id", run.run_id},
      {"algorithm", run.algorithm},
      {"adapter", Nested(spec, "algorithm", "adapter")},
      {"parameters", parameters.is_null() ? json::object() : parameters},
      {"parameters_text", run.parameters},
      {"sequence", run.sequence},
      {"noise", run.noise},
      {"iteration", run.iteration},
      {"seed", FieldOrNull(spec, "seed")},
      {"seeding", run.seeding},
      {"seeded", run.seeding == "seeded" || run.seeding == "deterministic"},
      {"odometry_is_reference", run.odometry_is_reference},
      {"flags", ToJson(run.flags)},
      {"status", RunStatusName(run.status)},
      {"failure_kind", FieldOrNull(result, "failure_kind")},
      {"reason", FieldOrNull(result, "reason")},
      {"exit_code", FieldOrNull(result, "exit_code")},
      {"signal", FieldOrNull(result, "signal")},
      {"wall_s", FieldOrNull(result, "wall_s")},
      {"cpu_s", FieldOrNull(result, "cpu_s")},
      {"peak_rss_kb", FieldOrNull(result, "peak_rss_kb")},
      {"run_dir", run.run_dir},
      {"ground_truth", Nested(spec, "sequence", "ground_truth")},
      {"reference", ReferenceMeaning(spec)},
      {"odometry", OdometryModeOfRunJson(spec)},
      {"reference_floor", FieldOrNull(result, "reference_floor")},
      {"metrics", std::move(metrics)},
      {"units", std::move(units)},
      {"outputs", outputs.is_null() ? json::object() : outputs},
  };
}

json BuildSummaryJson(const std::vector<RunRecord>& runs, const DigestedValidityStudy& study,
                      const std::string& generated_at) {
  json listed = json::array();
  std::size_t ok = 0;
  for (const RunRecord& run : runs) {
    listed.push_back(SummarizeRun(run));
    if (run.status == RunStatus::kOk) ++ok;
  }
  json groups = json::array();
  for (const GroupSummary& group : SummarizeGroups(runs)) groups.push_back(ToJson(group));
  json summary{{"generated_at", generated_at},
               {"groups", std::move(groups)},
               {"runs", std::move(listed)},
               {"counts",
                {{"total", runs.size()},
                 {RunStatusName(RunStatus::kOk), ok},
                 {RunStatusName(RunStatus::kFailed), runs.size() - ok}}}};
  // Which ground-truth-free metrics track real error (evaluator/validity); only with reference data.
  if (!study.study.empty()) {
    summary["validity"] = ToJson(study.study);
    summary["validity"]["inputs_sha256"] = study.inputs_sha256;
  }
  return summary;
}

void WriteSummaryJson(const std::vector<RunRecord>& runs, const DigestedValidityStudy& study,
                      const std::filesystem::path& file) {
  // Replacement of invalid UTF-8 (a reason quoting a program's garbled output) keeps the file writable.
  // Compact: indentation was 40 % of a large sweep's file (jq or a browser shows it indented).
  const std::string text =
      BuildSummaryJson(runs, study, UtcNowIso8601()).dump(-1, ' ', false, json::error_handler_t::replace) + "\n";
  WriteFileAtomically(file, text);
}

}  // namespace slamsweep::orchestrator::inline store
