#include "orchestrator/config/sweep_config.h"

#include <fmt/format.h>

#include <algorithm>
#include <regex>
#include <set>

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "evaluator/core/utf8_text.h"
#include "orchestrator/config/algorithm_config.h"
#include "orchestrator/config/cell_filter.h"
#include "orchestrator/config/sequence_config.h"
#include "orchestrator/run/spec_checks.h"
#include "orchestrator/config/yaml_fields.h"

namespace slamsweep::orchestrator::inline config {
namespace {

using evaluator::InputError;

constexpr std::string_view kMetrics[] = {"ape_trans",
                                         "ape_rot",
                                         "rpe_trans",
                                         "rpe_rot",
                                         "relations_trans",
                                         "relations_rot",
                                         "occupied_to_free_unknown",
                                         "occupied_to_all",
                                         "unknown_to_all",
                                         "corners",
                                         "enclosed_areas"};
constexpr std::string_view kStatistics[] = {"rmse", "mean", "median", "std", "min", "max", "sse", "n", "value"};

bool IsSafeName(const std::string& name) {
  return !name.empty() && name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.-") ==
                              std::string::npos;
}

/// Runs `check` (which throws unlocated InputErrors naming a field path) and locates its error at `node`.
template <typename Check>
auto LocatedCheck(const std::filesystem::path& file, const YAML::Node& node, Check&& check) -> decltype(check()) {
  try {
    return check();
  } catch (const InputError& error) {
    FailAt(file, node, error.what());
  }
}

std::filesystem::path Anchored(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::path path = text;
  if (path.is_relative()) path = file.parent_path() / path;
  return path.lexically_normal();
}

SeedPolicy ParseSeedPolicy(YamlFields& fields) {
  const std::string text = fields.Text("seed_policy", "per_iteration");
  for (SeedPolicy policy : {SeedPolicy::kPerIteration, SeedPolicy::kPerRun, SeedPolicy::kFixed}) {
    if (text == SeedPolicyName(policy)) return policy;
  }
  FailExpected(fields.file(), fields.Get("seed_policy"), fields.PathOf("seed_policy"),
               "per_iteration, per_run or fixed");
}

EvaluationOptions ParseEvaluation(const std::filesystem::path& file, const YAML::Node& node) {
  EvaluationOptions evaluation;
  if (!node.IsDefined() || node.IsNull()) return evaluation;
  YamlFields fields(file, node, "evaluation");
  ReadEvaluationFields(fields, evaluation);
  if (const YAML::Node segments = fields.Get("rpe_segments_m"); segments.IsDefined() && !segments.IsNull()) {
    LocatedCheck(file, segments, [&] {
      evaluation.rpe_segments_m = ParseSegmentLengths(YamlToJson(segments), fields.PathOf("rpe_segments_m"));
    });
  }
  fields.Finish();
  LocatedCheck(file, node, [&] { ValidateEvaluationOptions(evaluation, "evaluation"); });
  return evaluation;
}

std::vector<Threshold> ParseThresholds(const std::filesystem::path& file, const YAML::Node& node) {
  std::vector<Threshold> thresholds;
  if (!node.IsDefined() || node.IsNull()) return thresholds;
  if (!node.IsSequence()) FailExpected(file, node, "thresholds", "a list of {metric, statistic, max/min}");
  for (std::size_t i = 0; i < node.size(); ++i) {
    YamlFields fields(file, node[i], fmt::format("thresholds[{}]", i));
    Threshold threshold;
    threshold.metric = fields.RequiredText("metric");
    // The segment RPE's metrics name their length (segment_drift_10m: orchestrator/worker/run_metrics.h).
    static const std::regex kSegmentMetric("segment_(trans|drift|rot)_[0-9]+(p[0-9]+)?m");
    if (!OneOf(threshold.metric, kMetrics) && !std::regex_match(threshold.metric, kSegmentMetric)) {
      FailExpected(file, fields.Get("metric"), fields.PathOf("metric"),
                   "one of " + Choices(kMetrics) + ", or segment_trans|drift|rot_<length>m");
    }
    threshold.statistic = fields.Text("statistic", threshold.statistic);
    if (!OneOf(threshold.statistic, kStatistics)) {
      FailExpected(file, fields.Get("statistic"), fields.PathOf("statistic"), "one of " + Choices(kStatistics));
    }
    if (fields.Has("max")) threshold.max = fields.Number("max", 0.0);
    if (fields.Has("min")) threshold.min = fields.Number("min", 0.0);
    fields.Finish();
    LocatedCheck(file, node[i], [&] { ValidateThreshold(threshold, fmt::format("thresholds[{}]", i)); });
    thresholds.push_back(std::move(threshold));
  }
  return thresholds;
}

std::vector<NoiseSpec> ParseNoise(const std::filesystem::path& file, const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return {NoiseSpec{}};
  if (!node.IsSequence() || node.size() == 0) FailExpected(file, node, "noise", "a non-empty list of noise settings");
  std::vector<NoiseSpec> settings;
  std::set<std::string, std::less<>> names;
  for (std::size_t i = 0; i < node.size(); ++i) {
    YamlFields fields(file, node[i], fmt::format("noise[{}]", i));
    NoiseSpec noise;
    noise.name = fields.RequiredText("name");
    if (!names.insert(noise.name).second) {
      FailAt(file, fields.Get("name"),
             fmt::format("{}: expected a unique name, got '{}' a second time", fields.PathOf("name"), noise.name));
    }
    if (const YAML::Node odometry = fields.Get("odometry"); odometry.IsDefined() && !odometry.IsNull()) {
      if (!odometry.IsMap()) FailExpected(file, odometry, fields.PathOf("odometry"), "a map of odometry noise fields");
      noise.odometry = LocatedCheck(file, odometry, [&] {
        return evaluator::OdometryNoiseFromJson(YamlToJson(odometry), fields.PathOf("odometry"));
      });
    }
    if (const YAML::Node range = fields.Get("range"); range.IsDefined() && !range.IsNull()) {
      if (!range.IsMap()) FailExpected(file, range, fields.PathOf("range"), "a map of range noise fields");
      noise.range = LocatedCheck(
          file, range, [&] { return evaluator::RangeNoiseFromJson(YamlToJson(range), fields.PathOf("range")); });
    }
    fields.Finish();
    settings.push_back(std::move(noise));
  }
  return settings;
}

template <typename Item, typename Parse>
std::vector<Item> ParseNamedList(const std::filesystem::path& file, const YAML::Node& node, std::string_view key,
                                 Parse&& parse, const std::string& (*name_of)(const Item&)) {
  if (!node.IsDefined()) FailAt(file, YAML::Node(), fmt::format("{}: missing (required)", key));
  if (!node.IsSequence() || node.size() == 0) FailExpected(file, node, key, "a non-empty list");
  std::vector<Item> items;
  std::set<std::string, std::less<>> names;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string path = fmt::format("{}[{}]", key, i);
    Item item = parse(node[i], path);
    if (!names.insert(name_of(item)).second) {
      FailAt(file, node[i], fmt::format("{}: expected a unique name, got '{}' a second time", path, name_of(item)));
    }
    items.push_back(std::move(item));
  }
  return items;
}

const std::string& AlgorithmName(const AlgorithmConfig& algorithm) { return algorithm.name; }
const std::string& SequenceName(const SequenceSpec& sequence) { return sequence.entry.name; }

evaluator::Catalog LoadCatalog(const std::filesystem::path& file, YamlFields& fields, const SweepConfigContext& context,
                               std::filesystem::path& catalog_path) {
  const YAML::Node node = fields.Get("catalog");
  catalog_path = context.default_catalog;
  if (node.IsDefined() && !node.IsNull()) {
    catalog_path = Anchored(file, fields.Text("catalog", ""));
    RequireAllowedPath(context.policy, file, node, "catalog", "dataset catalog file", catalog_path);
  }
  std::error_code error;
  if (!std::filesystem::is_regular_file(catalog_path, error)) {
    // Without `catalog:` the default only matters when a sequence names a catalog entry (LookUp says so).
    if (!node.IsDefined() || node.IsNull()) return evaluator::Catalog{catalog_path, {}};
    FailAt(file, node.IsDefined() ? node : fields.node(),
           fmt::format("catalog: expected a dataset catalog file, got no such file {}", catalog_path.string()));
  }
  return evaluator::ReadCatalog(catalog_path);
}

}  // namespace

std::string_view SeedPolicyName(SeedPolicy policy) {
  switch (policy) {
    case SeedPolicy::kPerIteration:
      return "per_iteration";
    case SeedPolicy::kPerRun:
      return "per_run";
    case SeedPolicy::kFixed:
      return "fixed";
  }
  return "per_iteration";
}

namespace {

// The `regression:` block: strict keys, values range-checked at the value.
RegressionConfig ParseRegression(const std::filesystem::path& file, const YAML::Node& node) {
  RegressionConfig regression;
  if (!node.IsDefined() || node.IsNull()) return regression;
  YamlFields fields(file, node, "regression");
  regression.alpha = fields.Number("alpha", regression.alpha);
  if (!(regression.alpha > 0.0 && regression.alpha < 1.0)) {
    FailExpected(file, fields.Get("alpha"), "regression.alpha", "a significance level in (0, 1), e.g. 0.05");
  }
  regression.min_effect = fields.Number("min_effect", regression.min_effect);
  if (!(regression.min_effect >= 0.0 && regression.min_effect <= 1.0)) {
    FailExpected(file, fields.Get("min_effect"), "regression.min_effect",
                 "a Cliff's delta magnitude in [0, 1], e.g. 0.2");
  }
  fields.Finish();
  return regression;
}

}  // namespace

SweepConfig ParseSweepConfig(std::string_view yaml_text, const std::filesystem::path& file,
                             const SweepConfigContext& context) {
  // yaml-cpp passes bytes through as they are; names and values end up in JSON, which takes only UTF-8.
  evaluator::RequireUtf8(yaml_text, file, "a sweep file is UTF-8");
  YAML::Node root;
  try {
    root = YAML::Load(std::string(yaml_text));
  } catch (const YAML::Exception& error) {
    throw InputError(fmt::format("{}:{}:{}: {}", file.string(), error.mark.line + 1, error.mark.column + 1, error.msg));
  }
  if (!root.IsMap()) throw InputError(file.string() + ":1:1: expected a sweep: a map with name, algorithms, sequences");
  YamlFields fields(file, root, "");
  SweepConfig config;
  config.source = file;
  config.name = fields.RequiredText("name");
  if (!IsSafeName(config.name)) FailExpected(file, fields.Get("name"), "name", "a name of [A-Za-z0-9_.-] characters");
  config.output_dir = Anchored(file, fields.Text("output", "out/" + config.name));
  const std::uint64_t iterations = fields.Unsigned("iterations", 1);
  if (iterations < 1 || iterations > 1000000) {
    FailExpected(file, fields.Get("iterations"), "iterations", "a whole number from 1 to 1000000");
  }
  config.iterations = static_cast<int>(iterations);
  config.seed = fields.Unsigned("seed", 0);
  config.seed_policy = ParseSeedPolicy(fields);
  config.workers = fields.Unsigned("workers", 0);
  config.failure_budget = fields.Unsigned("failure_budget", 0);
  config.evaluation = ParseEvaluation(file, fields.Get("evaluation"));
  config.thresholds = ParseThresholds(file, fields.Get("thresholds"));
  config.regression = ParseRegression(file, fields.Get("regression"));
  if (const std::string study = fields.Text("validity_study", ""); !study.empty()) {
    config.validity_study = Anchored(file, study);
    RequireAllowedPath(context.policy, file, fields.Get("validity_study"), "validity_study", "validity study file",
                       config.validity_study);
    if (!std::filesystem::is_regular_file(config.validity_study)) {
      FailExpected(
          file, fields.Get("validity_study"), "validity_study",
          "a summary.json of a sweep with reference data (" + config.validity_study.string() + " is not a file)");
    }
  }

  const YAML::Node algorithms = fields.Get("algorithms");
  if (!algorithms.IsDefined()) FailAt(file, root, "algorithms: missing (required: a list of algorithms)");
  config.algorithms = ParseNamedList<AlgorithmConfig>(
      file, algorithms, "algorithms",
      [&](const YAML::Node& node, const std::string& path) {
        return ParseAlgorithmConfig(file, node, path, context.policy);
      },
      &AlgorithmName);
  for (std::size_t i = 0; i < config.algorithms.size(); ++i) {
    if (config.algorithms[i].iterations && *config.algorithms[i].iterations > config.iterations) {
      const YAML::Node node = algorithms[i]["iterations"];
      FailExpected(file, node, fmt::format("algorithms[{}].iterations", i),
                   fmt::format("at most the sweep's iterations ({})", config.iterations));
    }
  }

  const YAML::Node sequences = fields.Get("sequences");
  if (!sequences.IsDefined()) FailAt(file, root, "sequences: missing (required: a list of sequences)");
  const evaluator::Catalog catalog = LoadCatalog(file, fields, context, config.catalog);
  config.sequences = ParseNamedList<SequenceSpec>(
      file, sequences, "sequences",
      [&](const YAML::Node& node, const std::string& path) {
        return ParseSequenceConfig(file, node, path, catalog, context.variables, context.policy);
      },
      &SequenceName);

  config.noise = ParseNoise(file, fields.Get("noise"));
  config.exclude = ParseCellFilters(file, fields.Get("exclude"), "exclude", config, /*is_include=*/false);
  config.include = ParseCellFilters(file, fields.Get("include"), "include", config, /*is_include=*/true);
  fields.Finish();
  return config;
}

SweepConfig ReadSweepConfig(const std::filesystem::path& file, const SweepConfigContext& context) {
  return ParseSweepConfig(evaluator::ReadTextFile(file), file, context);
}

}  // namespace slamsweep::orchestrator::inline config
