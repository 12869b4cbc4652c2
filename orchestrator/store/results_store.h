#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "orchestrator/run/run_flags.h"
#include "orchestrator/run/run_record.h"
#include "orchestrator/run/run_status.h"
#include "orchestrator/store/sqlite_db.h"
#include "orchestrator/store/store_schema.h"
#include "orchestrator/store/sweeps_table.h"
#include "orchestrator/store/utc_now.h"

namespace slamsweep::orchestrator {

/// results.sqlite: the index of an output directory (result.json in each run folder is the commit point of a run,
/// the store indexes what the folders hold). Safe for several processes at once: WAL journal,
/// 10 s busy timeout, every write in one immediate transaction, so a process killed at any moment leaves
/// either the old or the new state of a run.
class ResultsStore {
 public:
  /// Opens `file`, creating it (and the schema) when missing. Throws InputError naming the file when it is
  /// not a slamsweep results database, is corrupt, or has a newer schema version.
  static ResultsStore Open(const std::filesystem::path& file);
  /// As Open, but a missing file is an InputError (for reading other output directories, e.g. merge inputs).
  static ResultsStore OpenExisting(const std::filesystem::path& file);

  const std::filesystem::path& file() const { return db_.file(); }

  /// Inserts a sweep with status "running"; returns its id.
  std::int64_t BeginSweep(const SweepInfo& info) { return InsertSweep(db_, info); }
  void FinishSweep(std::int64_t sweep_id, SweepStatus status, std::int64_t run_count) {
    MarkSweepFinished(db_, sweep_id, status, run_count);
  }
  std::vector<StoredSweep> Sweeps() const { return ReadSweeps(db_); }
  /// The id of a sweep equal to `sweep` (same name, config digest, start time, host), adding it when there is
  /// none; used by merge so that merging the same shard twice does not duplicate its sweep.
  std::int64_t ImportSweep(const StoredSweep& sweep) { return FindOrInsertSweep(db_, sweep); }

  /// Records (or replaces) one run: its row, its metrics and metric specifications, in one transaction.
  /// `run_spec` is run.json, `result` is result.json (DESIGN.md). Throws InputError naming the field when
  /// either lacks what the store needs (run_id, a recorded status (RecordedRunStatus), well-formed metrics).
  void RecordRun(std::int64_t sweep_id, const nlohmann::json& run_spec, const nlohmann::json& result,
                 const std::string& run_dir_relative);

  /// Records (or replaces) a run read from another store (merge): its row as that store keeps it, digest and
  /// flags included.
  void ImportRun(std::int64_t sweep_id, const RunRecord& run, const std::string& run_dir_relative);

  /// Between BeginBatch and CommitBatch, RecordRun and ImportRun write in one transaction (merge: a
  /// thousand runs in one commit instead of a thousand). A batch not committed is rolled back.
  void BeginBatch();
  void CommitBatch();

  /// What tells one recording of a run from another, for every recorded run at once (merge).
  struct RecordedIdentity {
    std::uint64_t result_digest = 0;
    RunFlags flags;
    std::string finished_at;
    std::string run_dir;
  };
  std::map<std::string, RecordedIdentity> RecordedIdentities() const;

  /// kOk or kFailed, or empty when the run was never recorded.
  std::optional<RunStatus> StatusOf(const std::string& run_id) const;
  std::optional<RunRecord> FindRun(const std::string& run_id) const;
  /// Adds `flags` to a recorded run (its flags column, which `result`'s flags mirror); false when the run
  /// was never recorded. The sweep marks a run it reuses under another build or evaluation "stale" this way.
  bool AddRunFlags(const std::string& run_id, const RunFlags& flags);
  /// Every run, ordered by sequence, algorithm, noise, iteration, run id.
  std::vector<RunRecord> Runs() const;

  /// Median wall_s of the ok runs per "<algorithm>\t<sequence>", to start the longest runs first.
  std::map<std::string, double> TypicalWallSeconds() const;

  /// Test hook: called inside RecordRun's transaction after the run row is written and before its metrics are,
  /// so a test can kill the process at the worst moment.
  void SetMidTransactionHookForTesting(std::function<void()> hook) { mid_transaction_hook_ = std::move(hook); }

 private:
  explicit ResultsStore(SqliteDb db) : db_(std::move(db)) {}
  static ResultsStore OpenImpl(const std::filesystem::path& file, bool create);
  void InitializeSchema();
  /// RecordRun's writes, inside the caller's transaction.
  void WriteRun(std::int64_t sweep_id, const nlohmann::json& run_spec, const nlohmann::json& result,
                const std::string& run_dir_relative, const RunFlags& flags,
                std::optional<std::uint64_t> result_digest = std::nullopt);
  std::vector<RunRecord> QueryRuns(const std::string& where, const std::string& run_id) const;

  /// Runs `write` in the open batch, else in a transaction of its own; a failure forgets the cached ids.
  void WriteInTransaction(const std::function<void()>& write);
  /// A prepared statement kept for the store's lifetime (reset before it is handed out).
  SqliteStatement& Cached(const std::string& sql);
  /// DocumentId through the cache of documents already seen.
  std::int64_t Document(const nlohmann::json& value);

  SqliteDb db_;
  // Declared after db_: statements are finalized before the connection closes.
  std::map<std::string, std::unique_ptr<SqliteStatement>> statements_;
  /// Ids of metric names and documents already seen: rows of both are never changed or deleted.
  std::map<std::tuple<std::string, std::string, std::string>, std::int64_t> metric_name_ids_;
  std::map<std::int64_t, std::pair<std::int64_t, std::string>> document_ids_;
  /// The open batch transaction (BeginBatch); it refers to db_, so the store is not moved during a batch.
  std::unique_ptr<SqliteTransaction> batch_;
  std::function<void()> mid_transaction_hook_;
};

/// "<algorithm>\t<sequence>", the key of TypicalWallSeconds().
std::string TypicalWallKey(const std::string& algorithm, const std::string& sequence);

}  // namespace slamsweep::orchestrator
