#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "orchestrator/run/run_flags.h"
#include "orchestrator/run/run_record.h"
#include "orchestrator/run/run_status.h"
#include "orchestrator/store/run_lookups.h"
#include "orchestrator/store/run_writer.h"
#include "orchestrator/store/sqlite_db.h"
#include "orchestrator/store/store_schema.h"
#include "orchestrator/store/sweeps_table.h"
#include "orchestrator/store/utc_now.h"

namespace slamsweep::orchestrator::inline store {

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

  const std::filesystem::path& file() const { return db_->file(); }

  /// Inserts a sweep with status "running"; returns its id.
  std::int64_t BeginSweep(const SweepInfo& info) { return InsertSweep(*db_, info); }
  void FinishSweep(std::int64_t sweep_id, SweepStatus status, std::int64_t run_count) {
    MarkSweepFinished(*db_, sweep_id, status, run_count);
  }
  std::vector<StoredSweep> Sweeps() const { return ReadSweeps(*db_); }
  /// The id of a sweep equal to `sweep` (same name, config digest, start time, host), adding it when there is
  /// none; used by merge so that merging the same shard twice does not duplicate its sweep.
  std::int64_t ImportSweep(const StoredSweep& sweep) { return FindOrInsertSweep(*db_, sweep); }

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
  void BeginBatch() { writer_.BeginBatch(); }
  void CommitBatch() { writer_.CommitBatch(); }

  /// What tells one recording of a run from another, for every recorded run at once (merge).
  using RecordedIdentity = RecordedRunIdentity;
  std::map<std::string, RecordedIdentity> RecordedIdentities() const { return ReadRecordedIdentities(*db_); }

  /// kOk or kFailed, or empty when the run was never recorded.
  std::optional<RunStatus> StatusOf(const std::string& run_id) const { return ReadRunStatus(*db_, run_id); }
  std::optional<RunRecord> FindRun(const std::string& run_id) const;
  /// Adds `flags` to a recorded run (its flags column, which `result`'s flags mirror); false when the run
  /// was never recorded. The sweep marks a run it reuses under another build or evaluation "stale" this way.
  bool AddRunFlags(const std::string& run_id, const RunFlags& flags) { return AddToRunFlags(*db_, run_id, flags); }
  /// Every run, ordered by sequence, algorithm, noise, iteration, run id.
  std::vector<RunRecord> Runs() const;

  /// Median wall_s of the ok runs per "<algorithm>\t<sequence>" (TypicalWallKey), to start the longest runs first.
  std::map<std::string, double> TypicalWallSeconds() const { return ReadTypicalWallSeconds(*db_); }

  /// Test hook: called inside RecordRun's transaction after the run row is written and before its metrics are,
  /// so a test can kill the process at the worst moment.
  void SetMidTransactionHookForTesting(std::function<void()> hook) {
    writer_.SetMidTransactionHookForTesting(std::move(hook));
  }

 private:
  explicit ResultsStore(SqliteDb db) : db_(std::make_unique<SqliteDb>(std::move(db))), writer_(*db_) {}
  static ResultsStore OpenImpl(const std::filesystem::path& file, bool create);
  void InitializeSchema();

  /// On the heap so that the writer's reference to it survives moving the store.
  std::unique_ptr<SqliteDb> db_;
  /// Declared after db_: its statements are finalized and its batch rolled back before the connection closes.
  RunWriter writer_;
};

}  // namespace slamsweep::orchestrator::inline store
