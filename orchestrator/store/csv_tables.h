#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "orchestrator/store/group_summary.h"
#include "evaluator/validity/metric_validity.h"
#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator::inline store {

/// summary.csv (RFC 4180): one row per comparison group: sequence, algorithm, parameters ("k=v;..."),
/// noise, n_runs, n_ok, n_failed, odometry_is_reference, seeding, flags, build (the group's
/// BuildSignature when runs of its comparison group were computed by several builds, else empty),
/// then for every headline metric
/// (IsHeadlineStatistic) that any group has, "<metric>.<statistic>.n|mean|std|min|max" over the
/// group's ok runs (empty when the group has none; std empty for n < 2). Numbers are the shortest
/// text that reads back to the same double.
std::string GroupsCsv(const std::vector<GroupSummary>& groups);

/// runs.csv: one row per run: identity (run_id, sequence, algorithm, parameters, noise, iteration,
/// seed), status, failure_kind, reason, odometry_is_reference, seeding, wall_s, cpu_s, peak_rss_kb,
/// then one column per flat metric "<metric>.<statistic>" that any run has.
std::string RunsCsv(const std::vector<RunRecord>& runs);

/// validity.csv: summary.json's "validity" table, one row per correlation: candidate, target,
/// sequence (empty = all sequences), pooling, runs, strata, spearman_rho, ci_low, ci_high,
/// resamples_defined, verdict (empty numbers where the verdict is "too few runs" or "no variation").
std::string ValidityCsv(const evaluator::ValidityStudy& study);

/// Writes OUTPUT_DIR/summary.csv, OUTPUT_DIR/runs.csv and, unless `study` (ValidityStudyOf(runs).study) is
/// empty, OUTPUT_DIR/validity.csv atomically.
void WriteCsvTables(const std::vector<RunRecord>& runs, const evaluator::ValidityStudy& study,
                    const std::filesystem::path& output_dir);

}  // namespace slamsweep::orchestrator::inline store
