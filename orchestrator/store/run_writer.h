#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include <nlohmann/json.hpp>

#include "orchestrator/run/run_flags.h"
#include "orchestrator/store/sqlite_db.h"

namespace slamsweep::orchestrator::inline store {

/// Writes runs into results.sqlite (the runs, metric_values and metric_spec_refs rows, and the documents and
/// metric names they refer to). Keeps the statements it runs for every run prepared, and the ids of the metric
/// names and documents it has seen, for the lifetime of the connection it writes to.
class RunWriter {
 public:
  /// Writes to `db`, which outlives the writer and keeps its address (the writer's statements belong to it).
  explicit RunWriter(SqliteDb& db) : db_(&db) {}

  /// Write in the open batch, else in a transaction of its own; a failure forgets the cached ids.
  void Record(std::int64_t sweep_id, const nlohmann::json& run_spec, const nlohmann::json& result,
              const std::string& run_dir_relative, const RunFlags& flags,
              std::optional<std::uint64_t> result_digest = std::nullopt);

  /// Records (or replaces) one run inside the caller's transaction: an earlier recording of its run id goes
  /// with its metric rows. `result_digest` keeps a digest from another store; without it the digest is
  /// computed from `result`. Throws InputError naming the field when run.json or result.json lacks what the
  /// store needs (run_id, a recorded status, well-formed metrics).
  void Write(std::int64_t sweep_id, const nlohmann::json& run_spec, const nlohmann::json& result,
             const std::string& run_dir_relative, const RunFlags& flags,
             std::optional<std::uint64_t> result_digest = std::nullopt);

  /// Between BeginBatch and CommitBatch, Record writes in one transaction. A batch not committed is rolled
  /// back when the writer goes.
  void BeginBatch();
  void CommitBatch();

  /// Called inside Write after the run row is written and before its metrics are.
  void SetMidTransactionHookForTesting(std::function<void()> hook) { mid_transaction_hook_ = std::move(hook); }

 private:
  /// Deletes the rows of an earlier recording of `run_id`.
  void RemoveRecording(const std::string& run_id);
  /// The metric_values rows of run row `run`: result.json's metrics, each listed once.
  void InsertMetricValues(std::int64_t run, const nlohmann::json& metrics);
  /// The id of a metric name (metric, statistic, unit), added when new.
  std::int64_t MetricNameId(const std::tuple<std::string, std::string, std::string>& name);
  /// The metric_spec_refs rows of run row `run`: how each metric of result.json's metric_details was measured.
  void InsertMetricSpecifications(std::int64_t run, const nlohmann::json& details);
  /// A prepared statement kept for the writer's lifetime (reset before it is handed out).
  SqliteStatement& Cached(const std::string& sql);
  /// DocumentId through the cache of documents already seen.
  std::int64_t Document(const nlohmann::json& value);
  /// After a rollback: ids cached meanwhile may name rows that never were.
  void ForgetCachedIds();

  SqliteDb* db_;
  std::map<std::string, std::unique_ptr<SqliteStatement>> statements_;
  /// Ids of metric names and documents already seen: rows of both are never changed or deleted.
  std::map<std::tuple<std::string, std::string, std::string>, std::int64_t> metric_name_ids_;
  std::map<std::int64_t, std::pair<std::int64_t, std::string>> document_ids_;
  /// The open batch transaction (BeginBatch).
  std::unique_ptr<SqliteTransaction> batch_;
  std::function<void()> mid_transaction_hook_;
};

}  // namespace slamsweep::orchestrator::inline store
