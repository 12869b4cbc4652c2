#include "orchestrator/store/csv_tables.h"

#include <fmt/format.h>

#include <map>
#include <optional>
#include <set>
#include <utility>

#include "orchestrator/files/atomic_file.h"

namespace slamsweep::orchestrator::inline store {
namespace {

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string Number(std::optional<double> value) { return value ? fmt::format("{}", *value) : ""; }

std::string JsonScalar(const nlohmann::json& value) {
  if (value.is_null()) return "";
  if (value.is_string()) return value.get<std::string>();
  return value.dump();
}

const nlohmann::json& Field(const nlohmann::json& object, const char* key) {
  static const nlohmann::json kNull;
  if (!object.is_object()) return kNull;
  const auto found = object.find(key);
  return found == object.end() ? kNull : *found;
}

std::string Row(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) line += ',';
    line += CsvField(fields[i]);
  }
  line += '\n';
  return line;
}

}  // namespace

std::string GroupsCsv(const std::vector<GroupSummary>& groups) {
  std::set<std::pair<std::string, std::string>> headline;
  for (const GroupSummary& group : groups) {
    for (const MetricAggregate& aggregate : group.metrics) {
      if (IsHeadlineStatistic(aggregate.metric, aggregate.statistic)) {
        headline.emplace(aggregate.metric, aggregate.statistic);
      }
    }
  }
  std::vector<std::string> header = {
      "sequence", "algorithm", "parameters", "noise", "odometry", "n_runs", "n_ok", "n_failed", "odometry_is_reference",
      "seeding",  "flags",     "build"};
  for (const auto& [metric, statistic] : headline) {
    for (const char* part : {"n", "mean", "std", "min", "max"}) {
      header.push_back(fmt::format("{}.{}.{}", metric, statistic, part));
    }
  }
  std::string out = Row(header);
  for (const GroupSummary& group : groups) {
    std::vector<std::string> fields = {
        group.group.sequence, group.group.algorithm, group.group.parameters, group.group.noise, group.group.odometry,
        std::to_string(group.runs), std::to_string(group.ok), std::to_string(group.failed),
        group.odometry_is_reference ? "true" : "false", group.seeding, RunFlagsText(group.flags),
        // A build apart from the group's others is named; one build alone is not.
        group.build_split ? group.build : ""};
    for (const auto& [metric, statistic] : headline) {
      const MetricAggregate* found = nullptr;
      for (const MetricAggregate& aggregate : group.metrics) {
        if (aggregate.metric == metric && aggregate.statistic == statistic) found = &aggregate;
      }
      if (found == nullptr || found->summary.n == 0) {
        fields.insert(fields.end(), {"0", "", "", "", ""});
        continue;
      }
      const evaluator::MeanStd& s = found->summary;
      fields.insert(fields.end(), {std::to_string(s.n), Number(s.mean), Number(s.std), Number(s.min), Number(s.max)});
    }
    out += Row(fields);
  }
  return out;
}

std::string RunsCsv(const std::vector<RunRecord>& runs) {
  std::set<std::pair<std::string, std::string>> names;
  for (const RunRecord& run : runs) {
    for (const FlatMetric& metric : run.metrics) names.emplace(metric.metric, metric.statistic);
  }
  std::vector<std::string> header = {"run_id",
                                     "sequence",
                                     "algorithm",
                                     "parameters",
                                     "noise",
                                     "iteration",
                                     "seed",
                                     "status",
                                     "failure_kind",
                                     "reason",
                                     "odometry_is_reference",
                                     "seeding",
                                     "flags",
                                     "wall_s",
                                     "cpu_s",
                                     "peak_rss_kb"};
  for (const auto& [metric, statistic] : names) header.push_back(fmt::format("{}.{}", metric, statistic));
  std::string out = Row(header);
  for (const RunRecord& run : runs) {
    std::map<std::pair<std::string, std::string>, std::optional<double>> values;
    for (const FlatMetric& metric : run.metrics) values[{metric.metric, metric.statistic}] = metric.value;
    std::vector<std::string> fields = {run.run_id,
                                       run.sequence,
                                       run.algorithm,
                                       run.parameters,
                                       run.noise,
                                       std::to_string(run.iteration),
                                       JsonScalar(Field(run.run_spec, "seed")),
                                       std::string(RunStatusName(run.status)),
                                       JsonScalar(Field(run.result, "failure_kind")),
                                       JsonScalar(Field(run.result, "reason")),
                                       run.odometry_is_reference ? "true" : "false",
                                       run.seeding,
                                       RunFlagsText(run.flags),
                                       JsonScalar(Field(run.result, "wall_s")),
                                       JsonScalar(Field(run.result, "cpu_s")),
                                       JsonScalar(Field(run.result, "peak_rss_kb"))};
    for (const auto& name : names) {
      const auto found = values.find(name);
      fields.push_back(found == values.end() ? "" : Number(found->second));
    }
    out += Row(fields);
  }
  return out;
}

std::string ValidityCsv(const evaluator::ValidityStudy& study) {
  std::string out = Row({"candidate", "target", "sequence", "pooling", "runs", "strata", "spearman_rho", "ci_low",
                         "ci_high", "resamples_defined", "verdict"});
  for (const evaluator::ValidityCorrelation& c : study.correlations) {
    out += Row({c.candidate, c.target, c.sequence, std::string(evaluator::ValidityPoolingName(c.pooling)),
                std::to_string(c.runs), std::to_string(c.strata), Number(c.rho),
                Number(c.interval ? std::optional(c.interval->low) : std::nullopt),
                Number(c.interval ? std::optional(c.interval->high) : std::nullopt),
                c.interval ? std::to_string(c.interval->defined) : "",
                std::string(evaluator::ValidityVerdictName(c.verdict))});
  }
  return out;
}

void WriteCsvTables(const std::vector<RunRecord>& runs, const evaluator::ValidityStudy& study,
                    const std::filesystem::path& output_dir) {
  WriteFileAtomically(output_dir / "summary.csv", GroupsCsv(SummarizeGroups(runs)));
  WriteFileAtomically(output_dir / "runs.csv", RunsCsv(runs));
  if (!study.empty()) {
    WriteFileAtomically(output_dir / "validity.csv", ValidityCsv(study));
  } else {
    std::error_code ignored;
    std::filesystem::remove(output_dir / "validity.csv", ignored);  // none left from an earlier sweep
  }
}

}  // namespace slamsweep::orchestrator::inline store
