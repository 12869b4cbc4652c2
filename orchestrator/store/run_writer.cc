#include "orchestrator/store/run_writer.h"

#include <cstddef>
#include <vector>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/run/run_spec.h"
#include "orchestrator/run/run_status.h"
#include "orchestrator/run/stable_hash.h"
#include "orchestrator/store/json_lookup.h"
#include "orchestrator/store/runs_table.h"
#include "orchestrator/store/store_schema.h"

namespace slamsweep::orchestrator::inline store {
namespace {

using evaluator::InputError;
using nlohmann::json;

struct RunColumns {
  std::string run_id;
  RunStatus status = RunStatus::kFailed;
};

// Checks what the store cannot do without; other fields are stored as they are (null when absent).
RunColumns ValidateRun(const json& run_spec, const json& result) {
  if (!run_spec.is_object()) throw InputError("run.json: expected a JSON object");
  if (!result.is_object()) throw InputError("result.json: expected a JSON object");
  const json* run_id = FindField(run_spec, "run_id");
  if (run_id == nullptr || !run_id->is_string() || run_id->get_ref<const std::string&>().empty()) {
    throw InputError("run.json: run_id: expected a non-empty string");
  }
  RunColumns columns{run_id->get<std::string>(), {}};
  const std::string where = fmt::format("result.json of run {}", columns.run_id);
  if (const json* result_id = FindField(result, "run_id"); result_id != nullptr && *result_id != *run_id) {
    throw InputError(fmt::format("{}: run_id: expected \"{}\" (the run.json's), found {}", where, columns.run_id,
                                 StoredJsonText(*result_id)));
  }
  const json* status = FindField(result, "status");
  const std::optional<RunStatus> recorded = status != nullptr && status->is_string()
                                                ? RecordedRunStatus(status->get_ref<const std::string&>())
                                                : std::nullopt;
  if (!recorded) {
    throw InputError(fmt::format("{}: status: expected \"{}\" or \"{}\", found {}", where,
                                 RunStatusName(RunStatus::kOk), RunStatusName(RunStatus::kFailed),
                                 status == nullptr ? "nothing" : StoredJsonText(*status)));
  }
  columns.status = *recorded;
  if (const json* metrics = FindField(result, "metrics"); metrics != nullptr && !metrics->is_null()) {
    if (!metrics->is_array()) throw InputError(fmt::format("{}: metrics: expected an array", where));
    for (std::size_t i = 0; i < metrics->size(); ++i) {
      const json& m = (*metrics)[i];
      for (const char* key : {"metric", "statistic"}) {
        const json* field = FindField(m, key);
        if (field == nullptr || !field->is_string() || field->get_ref<const std::string&>().empty()) {
          throw InputError(fmt::format("{}: metrics[{}].{}: expected a non-empty string", where, i, key));
        }
      }
      const json& value = FieldOrNull(m, "value");
      if (!value.is_null() && !value.is_number()) {
        throw InputError(fmt::format("{}: metrics[{}].value: expected a number or null", where, i));
      }
      const json& unit = FieldOrNull(m, "unit");
      if (!unit.is_null() && !unit.is_string()) {
        throw InputError(fmt::format("{}: metrics[{}].unit: expected a string", where, i));
      }
    }
  }
  if (const json* details = FindField(result, "metric_details");
      details != nullptr && !details->is_null() && !details->is_object()) {
    throw InputError(fmt::format("{}: metric_details: expected an object", where));
  }
  return columns;
}

// What the worker measured on the data when it got that far, else what the plan expected.
json OdometryIsReferenceOf(const json& run_spec, const json& result) {
  const json& measured = FieldOrNull(result, "odometry_is_reference");
  return measured.is_boolean() ? measured : FieldOrNull(run_spec, "odometry_is_reference");
}

// What a query needs of a metric's details: how it was measured (its "specification" or "parameters"),
// not the numbers (those are the run's metric values; the whole details stay in result.json).
json MetricSpecification(const json& details) {
  json kept = json::object();
  if (!details.is_object()) return kept;
  for (const char* key : {"specification", "parameters"}) {
    if (const auto it = details.find(key); it != details.end()) kept[key] = *it;
  }
  return kept;
}

// The identity of a result for merge: its whole text but the flags (compared on their own, since the
// store adds flags to a recorded run without its file).
std::int64_t ResultDigest(const json& result) {
  json without_flags = result;
  without_flags.erase("flags");
  return static_cast<std::int64_t>(Fnv1a64(StoredJsonText(without_flags)));
}

// The metrics in the order the worker listed them; a metric listed twice keeps its last value and place,
// as a JSON object with a repeated key would.
std::vector<const json*> DistinctMetrics(const json& metrics) {
  std::map<std::pair<std::string, std::string>, std::size_t> last;
  for (std::size_t i = 0; i < metrics.size(); ++i) {
    last[{metrics[i].at("metric").get<std::string>(), metrics[i].at("statistic").get<std::string>()}] = i;
  }
  std::vector<const json*> kept;
  for (std::size_t i = 0; i < metrics.size(); ++i) {
    if (last.at({metrics[i].at("metric").get<std::string>(), metrics[i].at("statistic").get<std::string>()}) == i) {
      kept.push_back(&metrics[i]);
    }
  }
  return kept;
}

}  // namespace

void RunWriter::Record(std::int64_t sweep_id, const json& run_spec, const json& result,
                       const std::string& run_dir_relative, const RunFlags& flags,
                       std::optional<std::uint64_t> result_digest) {
  try {
    if (batch_) {
      Write(sweep_id, run_spec, result, run_dir_relative, flags, result_digest);
      return;
    }
    SqliteTransaction transaction(*db_);
    Write(sweep_id, run_spec, result, run_dir_relative, flags, result_digest);
    transaction.Commit();
  } catch (...) {
    // Rolled back (or about to be, with the batch).
    ForgetCachedIds();
    throw;
  }
}

void RunWriter::Write(std::int64_t sweep_id, const json& run_spec, const json& result,
                      const std::string& run_dir_relative, const RunFlags& flags,
                      std::optional<std::uint64_t> result_digest) {
  const RunColumns columns = ValidateRun(run_spec, result);
  json spec_shared = run_spec;
  json spec_own = json::object();
  for (const char* key : kSpecOwnMembers) {
    if (const auto it = spec_shared.find(key); it != spec_shared.end()) {
      spec_own[key] = std::move(*it);
      spec_shared.erase(key);
    }
  }
  json result_shared = json::object();
  for (const char* key : kResultSharedMembers) {
    if (const json* value = FindField(result, key); value != nullptr) result_shared[key] = *value;
  }
  const std::int64_t spec_document = Document(spec_shared);
  const std::int64_t result_document = Document(result_shared);
  RemoveRecording(columns.run_id);
  {
    auto& insert = Cached(
        "INSERT INTO runs(run_id, sweep_id, algorithm, adapter, parameters_json, sequence, noise, iteration, seed, "
        "status, failure_kind, reason, exit_code, signal, wall_s, cpu_s, peak_rss_kb, started_at, finished_at, "
        "run_dir, parameters, odometry_is_reference, seeding, slamsweep_revision, flags, spec_shared, spec_own, "
        "result_shared, result_digest) "
        "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    const json& parameters = Nested(run_spec, "algorithm", "parameters");
    insert.Bind(1, columns.run_id).Bind(2, sweep_id);
    insert.BindJson(3, Nested(run_spec, "algorithm", "name")).BindJson(4, Nested(run_spec, "algorithm", "adapter"));
    if (parameters.is_null()) {
      insert.BindNull(5);
    } else {
      insert.Bind(5, std::string_view(StoredJsonText(parameters)));
    }
    insert.BindJson(6, Nested(run_spec, "sequence", "name")).BindJson(7, Nested(run_spec, "noise", "name"));
    insert.BindJson(8, FieldOrNull(run_spec, "iteration")).BindJson(9, FieldOrNull(run_spec, "seed"));
    insert.Bind(10, RunStatusName(columns.status));
    int index = 11;
    for (const char* key : kResultColumns) insert.BindJson(index++, FieldOrNull(result, key));
    insert.Bind(20, run_dir_relative);
    // Runs planned before run.json named its group: the text from their parameters.
    const json& group_parameters = Nested(run_spec, "group", "parameters");
    insert.BindJson(21, group_parameters.is_null() ? json(ParametersText(parameters)) : group_parameters);
    insert.BindJson(22, OdometryIsReferenceOf(run_spec, result));
    insert.BindJson(23, FieldOrNull(run_spec, "seeding"));
    insert.BindJson(24, Nested(run_spec, "build", "slamsweep_revision"));
    insert.Bind(25, RunFlagsText(flags));
    insert.Bind(26, spec_document).Bind(27, std::string_view(StoredJsonText(spec_own)));
    insert.Bind(28, result_document);
    insert.Bind(29, result_digest ? static_cast<std::int64_t>(*result_digest) : ResultDigest(result));
    insert.Run();
  }
  const std::int64_t run = db_->LastInsertRowId();
  if (mid_transaction_hook_) mid_transaction_hook_();
  if (const json* metrics = FindField(result, "metrics"); metrics != nullptr && metrics->is_array()) {
    InsertMetricValues(run, *metrics);
  }
  if (const json* details = FindField(result, "metric_details"); details != nullptr && details->is_object()) {
    InsertMetricSpecifications(run, *details);
  }
}

void RunWriter::RemoveRecording(const std::string& run_id) {
  for (const char* table : {"metric_values", "metric_spec_refs"}) {
    auto& remove = Cached(fmt::format("DELETE FROM {} WHERE run = (SELECT id FROM runs WHERE run_id = ?)", table));
    remove.Bind(1, run_id);
    remove.Run();
  }
  auto& remove = Cached("DELETE FROM runs WHERE run_id = ?");
  remove.Bind(1, run_id);
  remove.Run();
}

void RunWriter::InsertMetricValues(std::int64_t run, const json& metrics) {
  auto& insert = Cached("INSERT INTO metric_values(run, position, name, value) VALUES(?, ?, ?, ?)");
  std::int64_t position = 0;
  for (const json* m : DistinctMetrics(metrics)) {
    const json& unit = FieldOrNull(*m, "unit");
    const std::int64_t name = MetricNameId({m->at("metric").get<std::string>(), m->at("statistic").get<std::string>(),
                                            unit.is_string() ? unit.get<std::string>() : ""});
    insert.Reset();
    insert.Bind(1, run).Bind(2, position++).Bind(3, name).BindJson(4, FieldOrNull(*m, "value"));
    insert.Run();
  }
}

std::int64_t RunWriter::MetricNameId(const std::tuple<std::string, std::string, std::string>& name) {
  if (const auto known = metric_name_ids_.find(name); known != metric_name_ids_.end()) return known->second;
  // Another process may have added it meanwhile: insert unless there, then read its id.
  auto& add = Cached("INSERT OR IGNORE INTO metric_names(metric, statistic, unit) VALUES(?, ?, ?)");
  add.Bind(1, std::get<0>(name)).Bind(2, std::get<1>(name)).Bind(3, std::get<2>(name));
  add.Run();
  auto& find = Cached("SELECT id FROM metric_names WHERE metric = ? AND statistic = ? AND unit = ?");
  find.Bind(1, std::get<0>(name)).Bind(2, std::get<1>(name)).Bind(3, std::get<2>(name));
  if (!find.Step()) throw InputError(db_->file().string() + ": metric name not recorded");
  const std::int64_t id = metric_name_ids_.emplace(name, find.Int64(0)).first->second;
  // A statement left on a row keeps its read snapshot open, which would keep later writes (and a
  // table drop during a conversion) from starting.
  find.Reset();
  return id;
}

void RunWriter::InsertMetricSpecifications(std::int64_t run, const json& details) {
  auto& insert = Cached("INSERT INTO metric_spec_refs(run, metric, spec) VALUES(?, ?, ?)");
  for (const auto& [metric, detail] : details.items()) {
    const std::int64_t spec = Document(MetricSpecification(detail));
    insert.Reset();
    insert.Bind(1, run).Bind(2, metric).Bind(3, spec);
    insert.Run();
  }
}

void RunWriter::BeginBatch() {
  if (batch_) throw InputError(db_->file().string() + ": a batch of writes is already open");
  batch_ = std::make_unique<SqliteTransaction>(*db_);
}

void RunWriter::CommitBatch() {
  if (!batch_) return;
  std::unique_ptr<SqliteTransaction> batch = std::move(batch_);
  try {
    batch->Commit();
  } catch (...) {
    ForgetCachedIds();
    throw;
  }
}

SqliteStatement& RunWriter::Cached(const std::string& sql) {
  std::unique_ptr<SqliteStatement>& statement = statements_[sql];
  if (!statement) statement = db_->PrepareKept(sql);
  statement->Reset();
  return *statement;
}

std::int64_t RunWriter::Document(const json& value) {
  const std::string text = StoredJsonText(value);
  const auto digest = static_cast<std::int64_t>(Fnv1a64(text));
  if (const auto found = document_ids_.find(digest); found != document_ids_.end() && found->second.second == text) {
    return found->second.first;
  }
  const std::int64_t id = DocumentId(*db_, value);
  document_ids_[digest] = {id, text};
  return id;
}

void RunWriter::ForgetCachedIds() {
  metric_name_ids_.clear();
  document_ids_.clear();
}

}  // namespace slamsweep::orchestrator::inline store
