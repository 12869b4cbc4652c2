#pragma once

#include <optional>
#include <string>
#include <vector>

#include "orchestrator/run/run_record.h"
#include "orchestrator/store/sqlite_db.h"

namespace slamsweep::orchestrator::inline store {

/// Reading runs back from results.sqlite as RunRecords: each run's columns, its shared documents, metrics and
/// metric specifications, read in one snapshot so that a concurrent writer cannot pair a run with another
/// recording's metrics. Throws InputError naming the run when the database holds what the writer never stores.

/// Every run, ordered by sequence, algorithm, noise, iteration, run id.
std::vector<RunRecord> ReadRuns(const SqliteDb& db);

/// The run `run_id`, or nullopt when it was never recorded.
std::optional<RunRecord> ReadRun(const SqliteDb& db, const std::string& run_id);

}  // namespace slamsweep::orchestrator::inline store
