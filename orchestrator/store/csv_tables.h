#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "orchestrator/store/group_summary.h"
#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator {

/// summary.csv (RFC 4180): one row per comparison group: sequence, algorithm, parameters ("k=v;..."),
/// noise, n_runs, n_ok, n_failed, odometry_is_reference, seeding, then for every headline metric
/// (IsHeadlineStatistic) that any group has, "<metric>.<statistic>.n|mean|std|min|max" over the
/// group's ok runs (empty when the group has none; std empty for n < 2). Numbers are the shortest
/// text that reads back to the same double.
std::string GroupsCsv(const std::vector<GroupSummary>& groups);

/// runs.csv: one row per run: identity (run_id, sequence, algorithm, parameters, noise, iteration,
/// seed), status, failure_kind, reason, odometry_is_reference, seeding, wall_s, cpu_s, peak_rss_kb,
/// then one column per flat metric "<metric>.<statistic>" that any run has.
std::string RunsCsv(const std::vector<StoredRun>& runs);

/// Writes OUTPUT_DIR/summary.csv and OUTPUT_DIR/runs.csv atomically.
void WriteCsvTables(const std::vector<StoredRun>& runs, const std::filesystem::path& output_dir);

}  // namespace slamsweep::orchestrator
