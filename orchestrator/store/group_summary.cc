#include "orchestrator/store/group_summary.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <utility>

namespace slamsweep::orchestrator::inline store {
namespace {

/// result.json's metric_details.segment_rpe.specification.lengths_m; nullopt when the run has none.
std::optional<std::vector<double>> SegmentLengthsOf(const nlohmann::json& result) {
  const nlohmann::json::json_pointer pointer("/metric_details/segment_rpe/specification/lengths_m");
  if (!result.is_object() || !result.contains(pointer) || !result.at(pointer).is_array()) return std::nullopt;
  std::vector<double> lengths;
  for (const nlohmann::json& length : result.at(pointer)) {
    if (length.is_number()) lengths.push_back(length.get<double>());
  }
  return lengths;
}

void NoteSegmentLengths(GroupSummary& summary, const std::vector<double>& lengths, bool first) {
  if (!first && lengths != summary.segment_lengths_m) summary.segment_lengths_consistent = false;
  std::vector<double> merged;
  std::set_union(summary.segment_lengths_m.begin(), summary.segment_lengths_m.end(), lengths.begin(), lengths.end(),
                 std::back_inserter(merged));
  summary.segment_lengths_m = std::move(merged);
}

}  // namespace

std::vector<GroupSummary> SummarizeGroups(const std::vector<RunRecord>& runs) {
  struct Collected {
    GroupSummary summary;
    std::map<std::pair<std::string, std::string>, std::pair<std::string, std::vector<double>>> values;
    bool has_segments = false;
  };
  // Sequence and noise first: the rows that may be compared with each other end up next to each other.
  // Runs on recorded and on reference odometry never share a group.
  using GroupKey = std::tuple<std::string, std::string, std::string, std::string, std::string, std::string>;
  std::map<GroupKey, Collected> groups;
  std::map<std::tuple<std::string, std::string, std::string, std::string, std::string>, std::set<std::string>>
      builds_of;
  for (const RunRecord& run : runs) {
    const std::string build = BuildSignatureOfRunJson(run.run_spec);
    const std::string odometry = OdometryModeOfRunJson(run.run_spec);
    builds_of[{run.sequence, run.noise, run.algorithm, run.parameters, odometry}].insert(build);
    Collected& collected = groups[{run.sequence, run.noise, run.algorithm, run.parameters, odometry, build}];
    GroupSummary& summary = collected.summary;
    if (summary.runs == 0) {
      summary.group = ComparisonGroup{run.sequence, run.algorithm, run.parameters, run.noise, odometry};
      summary.build = build;
      summary.build_description = BuildDescriptionOfRunJson(run.run_spec);
      summary.seeding = run.seeding;
    } else if (summary.seeding != run.seeding) {
      summary.seeding = "mixed";
    }
    ++summary.runs;
    summary.odometry_is_reference = summary.odometry_is_reference || run.odometry_is_reference;
    summary.flags |= run.flags;
    if (run.status != RunStatus::kOk) {
      ++summary.failed;
      continue;
    }
    ++summary.ok;
    if (const std::optional<std::vector<double>> lengths = SegmentLengthsOf(run.result)) {
      NoteSegmentLengths(summary, *lengths, !collected.has_segments);
      collected.has_segments = true;
    }
    for (const FlatMetric& metric : run.metrics) {
      if (!metric.value) continue;
      auto& [unit, values] = collected.values[{metric.metric, metric.statistic}];
      if (unit.empty()) unit = metric.unit;
      values.push_back(*metric.value);
    }
  }
  std::vector<GroupSummary> summaries;
  for (auto& [key, collected] : groups) {
    const auto& [sequence, noise, algorithm, parameters, odometry, build] = key;
    collected.summary.build_split = builds_of.at({sequence, noise, algorithm, parameters, odometry}).size() > 1;
    for (const auto& [name, unit_values] : collected.values) {
      collected.summary.metrics.push_back(
          MetricAggregate{name.first, name.second, unit_values.first, evaluator::ComputeMeanStd(unit_values.second)});
    }
    summaries.push_back(std::move(collected.summary));
  }
  return summaries;
}

nlohmann::json ToJson(const GroupSummary& group) {
  nlohmann::json metrics = nlohmann::json::object();
  for (const MetricAggregate& aggregate : group.metrics) {
    const evaluator::MeanStd& s = aggregate.summary;
    metrics[aggregate.metric][aggregate.statistic] = {
        {"n", s.n},     {"mean", s.mean}, {"std", s.std ? nlohmann::json(*s.std) : nlohmann::json()},
        {"min", s.min}, {"max", s.max},   {"unit", aggregate.unit}};
  }
  return {{"sequence", group.group.sequence},
          {"algorithm", group.group.algorithm},
          {"parameters", group.group.parameters},
          {"noise", group.group.noise},
          {"odometry", group.group.odometry},
          {"build", group.build},
          {"build_split", group.build_split},
          {"build_description", group.build_description},
          {"n_runs", group.runs},
          {"n_ok", group.ok},
          {"n_failed", group.failed},
          {"odometry_is_reference", group.odometry_is_reference},
          {"flags", ToJson(group.flags)},
          {"seeding", group.seeding},
          {"metrics", std::move(metrics)},
          {"rpe_segments_m", group.segment_lengths_m},
          {"rpe_segments_consistent", group.segment_lengths_consistent}};
}

bool IsHeadlineStatistic(const std::string& metric, const std::string& statistic) {
  if (metric.starts_with("relations_") || metric.starts_with("segment_")) return statistic == "mean";
  return statistic == "rmse" || statistic == "value";
}

}  // namespace slamsweep::orchestrator::inline store
