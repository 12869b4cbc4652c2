#include "orchestrator/store/results_store.h"

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/store/run_reader.h"

namespace slamsweep::orchestrator::inline store {

using evaluator::InputError;

ResultsStore ResultsStore::Open(const std::filesystem::path& file) { return OpenImpl(file, true); }

ResultsStore ResultsStore::OpenExisting(const std::filesystem::path& file) { return OpenImpl(file, false); }

ResultsStore ResultsStore::OpenImpl(const std::filesystem::path& file, bool create) {
  ResultsStore store(SqliteDb::Open(file, create));
  store.InitializeSchema();
  return store;
}

void ResultsStore::InitializeSchema() {
  SqliteDb& db = *db_;
  const auto read_version = [&db] {
    auto version = db.Prepare("PRAGMA user_version");
    version.Step();
    return version.Int64(0);
  };
  const auto count_tables = [&db] {
    auto tables = db.Prepare("SELECT count(*) FROM sqlite_master WHERE type = 'table'");
    tables.Step();
    return tables.Int64(0);
  };
  // The first read is where SQLite notices a file that is not a database. Version and tables are read
  // in one snapshot: another process creating the schema between the two reads would otherwise make
  // a new store look like a foreign database (tables, version 0).
  std::int64_t version = 0;
  std::int64_t tables = 0;
  {
    db.Execute("BEGIN");
    try {
      version = read_version();
      tables = count_tables();
    } catch (...) {
      db.Execute("ROLLBACK");
      throw;
    }
    db.Execute("COMMIT");
  }
  if (version > kResultsSchemaVersion) {
    throw InputError(
        fmt::format("{}: results database schema version {} is newer than this slamsweep's ({}); "
                    "use a newer slamsweep or another output directory",
                    db.file().string(), version, kResultsSchemaVersion));
  }
  if (version == 0 && tables > 0) {
    throw InputError(
        fmt::format("{}: an SQLite database but not a slamsweep results database (it has tables and "
                    "no schema version); use another output directory",
                    db.file().string()));
  }
  // WAL lets readers (status, report) work while a sweep writes; it is a property of the file, kept once set.
  db.ExecuteRetryingWhileBusy("PRAGMA journal_mode = WAL");
  db.Execute("PRAGMA synchronous = NORMAL");
  if (version == kResultsSchemaVersion) return;
  SqliteTransaction transaction(db);
  // Another process may have created or migrated the schema between the first read and the write lock.
  const std::int64_t locked_version = read_version();
  if (locked_version == kResultsSchemaVersion) {
    transaction.Commit();
    return;
  }
  CreateOrMigrateSchema(db, locked_version, [this, &db](const V3Run& run) {
    const RunFlags flags = run.flags ? RunFlagsFromText(*run.flags, db.file().string() + ": runs.flags")
                                     : RunFlagsOf(run.spec, run.result);
    writer_.Write(run.sweep_id, run.spec, run.result, run.run_dir, flags);
  });
  transaction.Commit();
}

void ResultsStore::RecordRun(std::int64_t sweep_id, const nlohmann::json& run_spec, const nlohmann::json& result,
                             const std::string& run_dir_relative) {
  const RunFlags flags = RunFlagsOf(run_spec, result);
  writer_.Record(sweep_id, run_spec, result, run_dir_relative, flags);
}

void ResultsStore::ImportRun(std::int64_t sweep_id, const RunRecord& run, const std::string& run_dir_relative) {
  writer_.Record(sweep_id, run.run_spec, run.result, run_dir_relative, run.flags, run.result_digest);
}

std::optional<RunRecord> ResultsStore::FindRun(const std::string& run_id) const { return ReadRun(*db_, run_id); }

std::vector<RunRecord> ResultsStore::Runs() const { return ReadRuns(*db_); }

}  // namespace slamsweep::orchestrator::inline store
