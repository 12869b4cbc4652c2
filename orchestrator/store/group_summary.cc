#include "orchestrator/store/group_summary.h"

#include <map>
#include <utility>

namespace slamsweep::orchestrator {

std::vector<GroupSummary> SummarizeGroups(const std::vector<StoredRun>& runs) {
  struct Collected {
    GroupSummary summary;
    std::map<std::pair<std::string, std::string>, std::pair<std::string, std::vector<double>>> values;
  };
  // Sequence and noise first: the rows that may be compared with each other end up next to each other.
  std::map<std::tuple<std::string, std::string, std::string, std::string>, Collected> groups;
  for (const StoredRun& run : runs) {
    Collected& collected = groups[{run.sequence, run.noise, run.algorithm, run.parameters}];
    GroupSummary& summary = collected.summary;
    if (summary.runs == 0) {
      summary.group = ComparisonGroup{run.sequence, run.algorithm, run.parameters, run.noise};
      summary.seeding = run.seeding;
    } else if (summary.seeding != run.seeding) {
      summary.seeding = "mixed";
    }
    ++summary.runs;
    summary.odometry_is_reference = summary.odometry_is_reference || run.odometry_is_reference;
    if (run.status != "ok") {
      ++summary.failed;
      continue;
    }
    ++summary.ok;
    for (const StoredMetric& metric : run.metrics) {
      if (!metric.value) continue;
      auto& [unit, values] = collected.values[{metric.metric, metric.statistic}];
      if (unit.empty()) unit = metric.unit;
      values.push_back(*metric.value);
    }
  }
  std::vector<GroupSummary> summaries;
  for (auto& [key, collected] : groups) {
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
    metrics[aggregate.metric][aggregate.statistic] = {{"n", s.n},
                                                      {"mean", s.mean},
                                                      {"std", s.std ? nlohmann::json(*s.std) : nlohmann::json()},
                                                      {"min", s.min},
                                                      {"max", s.max},
                                                      {"unit", aggregate.unit}};
  }
  return {{"sequence", group.group.sequence},
          {"algorithm", group.group.algorithm},
          {"parameters", group.group.parameters},
          {"noise", group.group.noise},
          {"n_runs", group.runs},
          {"n_ok", group.ok},
          {"n_failed", group.failed},
          {"odometry_is_reference", group.odometry_is_reference},
          {"seeding", group.seeding},
          {"metrics", std::move(metrics)}};
}

bool IsHeadlineStatistic(const std::string& metric, const std::string& statistic) {
  if (metric.starts_with("relations_")) return statistic == "mean";
  return statistic == "rmse" || statistic == "value";
}

}  // namespace slamsweep::orchestrator
