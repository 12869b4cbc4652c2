#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/core/sample_summary.h"
#include "orchestrator/run/run_json.h"
#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator::inline store {

/// One flat metric (metric x statistic) over the ok runs of a group.
struct MetricAggregate {
  std::string metric;
  std::string statistic;
  std::string unit;
  evaluator::MeanStd summary;
};

/// Every run of one comparison group (same sequence, algorithm, parameters, noise) computed by one
/// build (BuildSignature), summarised. Nothing is ever pooled across groups: that is what makes two
/// rows comparable. Runs of one comparison group but different builds (a merge of shards built
/// apart, a --reuse-stale rerun) are separate groups, each marked `build_split`.
struct GroupSummary {
  ComparisonGroup group;
  /// BuildSignature of the runs' build identity ("" when run.json has none).
  std::string build;
  /// Another group holds runs of the same comparison group computed by another build.
  bool build_split = false;
  /// BuildDescriptionOfRunJson of the group's first run, for readers of a split.
  std::string build_description;
  std::size_t runs = 0;
  std::size_t ok = 0;
  std::size_t failed = 0;
  /// Some run of the group got the reference as odometry: an upper bound, not a SLAM result.
  bool odometry_is_reference = false;
  /// The union of the runs' marks: a flagged group is shown, never ranked or marked best.
  RunFlags flags;
  /// The runs' seeding ("seeded", "deterministic", "unseeded"; "mixed" if they differ).
  std::string seeding;
  /// Sorted by metric, then statistic; only metrics some ok run has.
  std::vector<MetricAggregate> metrics;
  /// The segment lengths of the ok runs' segment RPE (ascending union), and whether every such run
  /// used exactly these: runs scored at other lengths (a --reuse-stale rerun) never share a
  /// segment_*_<L>m aggregate, whose name holds the length, but the group says so.
  std::vector<double> segment_lengths_m;
  bool segment_lengths_consistent = true;
};

/// The groups of `runs`, sorted by sequence, noise, algorithm, parameters, odometry mode
/// (OdometryModeOfRunJson), build.
std::vector<GroupSummary> SummarizeGroups(const std::vector<RunRecord>& runs);

/// {"sequence", "algorithm", "parameters", "noise", "odometry", "build", "build_split", "build_description", "n_runs",
/// "n_ok", "n_failed", "odometry_is_reference",
///  "flags", "seeding", "metrics": {metric: {statistic: {"n", "mean", "std", "min", "max", "unit"}}},
///  "rpe_segments_m": [...], "rpe_segments_consistent": bool}
nlohmann::json ToJson(const GroupSummary& group);

/// Whether a flat metric is the one a table shows for it: rmse of APE/RPE, mean of the relations
/// metric and of the segment RPE, value of the map metrics (summary.csv's columns).
bool IsHeadlineStatistic(const std::string& metric, const std::string& statistic);

}  // namespace slamsweep::orchestrator::inline store
