#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "orchestrator/run/run_status.h"
#include "orchestrator/store/sqlite_db.h"

namespace slamsweep::orchestrator::inline store {

/// What is known about a sweep when it starts.
struct SweepInfo {
  std::string name;
  std::string config_path;
  /// SHA-256 (or any stable digest) of the config file's bytes, to tell edited configs apart.
  std::string config_sha;
  /// ISO 8601 UTC; empty = now.
  std::string started_at;
  std::string host;
  std::string slamsweep_version;
  std::string command_line;
};

/// A row of the sweeps table.
struct StoredSweep {
  std::int64_t id = 0;
  SweepInfo info;
  std::string finished_at;
  /// kRunning until FinishSweep, then what the orchestrator reported.
  SweepStatus status = SweepStatus::kRunning;
  std::int64_t run_count = 0;
};

/// The sweeps table of results.sqlite; each write is a transaction of its own.

/// Inserts a sweep with status "running"; returns its id.
std::int64_t InsertSweep(SqliteDb& db, const SweepInfo& info);
/// Sets a sweep's end: finished now, with `status` and `run_count`.
void MarkSweepFinished(SqliteDb& db, std::int64_t sweep_id, SweepStatus status, std::int64_t run_count);
/// Every sweep, by id. Throws InputError on a status the store never writes.
std::vector<StoredSweep> ReadSweeps(const SqliteDb& db);
/// The id of a sweep equal to `sweep` (same name, config digest, start time, host), adding it when there is none.
std::int64_t FindOrInsertSweep(SqliteDb& db, const StoredSweep& sweep);

}  // namespace slamsweep::orchestrator::inline store
