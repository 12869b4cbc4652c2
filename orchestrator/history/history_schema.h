#pragma once

#include <cstdint>

#include "orchestrator/store/sqlite_db.h"

namespace slamsweep::orchestrator::inline history {

/// The history schema version this build writes (PRAGMA user_version). Version 2 keys every series by its
/// odometry mode as well (samples.odometry, cells.odometry).
inline constexpr int kHistorySchemaVersion = 2;

/// Tells a history file from a results.sqlite (both are slamsweep SQLite files with a user_version).
inline constexpr std::int64_t kHistoryApplicationId = 0x534C4853;  // "SLHS"

/// Creates the current schema in an empty database (from_version 0), or migrates an older one to it, inside the
/// caller's write transaction. From version 1 each night's series get the odometry mode its result directory's
/// runs say (OdometryModesOfResultDir), else "unknown" (or "mixed" when a cell's runs had both modes): never a
/// guessed "recorded".
void CreateOrMigrateHistorySchema(SqliteDb& db, std::int64_t from_version);

}  // namespace slamsweep::orchestrator::inline history
