#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "orchestrator/store/sqlite_db.h"

namespace slamsweep::orchestrator::inline store {

/// The schema version this build writes (PRAGMA user_version). A file with a higher version was
/// written by a newer slamsweep and is refused rather than misread.
inline constexpr int kResultsSchemaVersion = 4;

/// Creates the current schema in an empty database, or migrates an older one to it (inside the caller's
/// write transaction). `record_v3_run` re-records one run of a version 3 store in the new tables.
struct V3Run {
  std::int64_t sweep_id = 0;
  nlohmann::json spec;
  nlohmann::json result;
  std::string run_dir;
  /// The v3 flags column ("a;b"), or nullopt when NULL (the flags then follow from the files).
  std::optional<std::string> flags;
};
void CreateOrMigrateSchema(SqliteDb& db, std::int64_t from_version,
                           const std::function<void(const V3Run&)>& record_v3_run);

/// A JSON value kept once however many runs share it (the documents table): its id, added when new.
std::int64_t DocumentId(SqliteDb& db, const nlohmann::json& value);

}  // namespace slamsweep::orchestrator::inline store
