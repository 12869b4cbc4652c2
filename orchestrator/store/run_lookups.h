#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "orchestrator/run/run_flags.h"
#include "orchestrator/run/run_status.h"
#include "orchestrator/store/sqlite_db.h"

namespace slamsweep::orchestrator::inline store {

/// Lookups of a few columns of the runs table, without reading whole runs.

/// What tells one recording of a run from another (merge).
struct RecordedRunIdentity {
  std::uint64_t result_digest = 0;
  RunFlags flags;
  std::string finished_at;
  std::string run_dir;
};
/// The identity of every recorded run, by run id.
std::map<std::string, RecordedRunIdentity> ReadRecordedIdentities(const SqliteDb& db);

/// kOk or kFailed, or empty when the run was never recorded.
std::optional<RunStatus> ReadRunStatus(const SqliteDb& db, const std::string& run_id);

/// Adds `added` to a recorded run's flags column in one transaction; false when the run was never recorded.
bool AddToRunFlags(SqliteDb& db, const std::string& run_id, const RunFlags& added);

/// Median wall_s of the ok runs per TypicalWallKey.
std::map<std::string, double> ReadTypicalWallSeconds(const SqliteDb& db);

/// "<algorithm>\t<sequence>", the key of ReadTypicalWallSeconds.
std::string TypicalWallKey(const std::string& algorithm, const std::string& sequence);

}  // namespace slamsweep::orchestrator::inline store
