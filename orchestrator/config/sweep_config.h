#pragma once

// The sweep file format (every key, its default and meaning) is documented in docs/sweep-files.md.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/catalog/catalog.h"
#include "orchestrator/config/input_policy.h"
#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline config {

/// One swept parameter: its values in the order written (a scalar in the file is a list of one).
struct ParameterAxis {
  std::string name;
  /// Scalars: number, string or bool.
  std::vector<nlohmann::json> values;
};

/// An algorithm as written: like AlgorithmSpec, but each parameter may hold several values.
struct AlgorithmConfig {
  std::string name;
  std::string adapter;
  /// In the order written, which is the order of the cartesian product (first = slowest).
  std::vector<ParameterAxis> parameters;
  double timeout_s = 600.0;
  std::uint64_t memory_limit_mb = 0;
  std::uint64_t disk_limit_mb = kDefaultDiskLimitMb;
  std::uint64_t process_limit = kDefaultProcessLimit;
  bool network = false;
  std::optional<CommandDeclaration> command;
  /// Fewer iterations than the sweep's for this algorithm (1 for a deterministic program on data
  /// without a noise draw: more would repeat one result); at most the sweep's `iterations`, and
  /// capped by `--iterations` like it. Unset: the sweep's.
  std::optional<int> iterations;
};

enum class SeedPolicy { kPerIteration, kPerRun, kFixed };

/// "per_iteration", "per_run", "fixed".
std::string_view SeedPolicyName(SeedPolicy policy);

/// A cell pattern of `exclude:` / `include:`: every given field must match; absent fields match anything.
struct CellFilter {
  std::optional<std::string> algorithm;
  std::optional<std::string> sequence;
  std::optional<std::string> noise;
  /// Parameter name -> scalar value; only the named parameters are compared.
  nlohmann::json parameters = nlohmann::json::object();
};

/// When a change between two nights counts as a regression (orchestrator/history): the sweep's `regression:` block.
struct RegressionConfig {
  /// Significance level of the two-sided Mann-Whitney U test, in (0, 1).
  double alpha = 0.05;
  /// Minimum |Cliff's delta| of a reported change, in [0, 1].
  double min_effect = 0.2;
};

/// A sweep file, validated and resolved: paths absolute, catalog sequences looked up, noise parsed.
struct SweepConfig {
  /// The file it was read from (for messages).
  std::filesystem::path source;
  std::string name;
  std::filesystem::path output_dir;
  std::filesystem::path catalog;
  int iterations = 1;
  std::uint64_t seed = 0;
  SeedPolicy seed_policy = SeedPolicy::kPerIteration;
  /// Default --jobs; 0 = the number of cores.
  std::size_t workers = 0;
  /// Stop starting new runs after this many failures; 0 = never stop.
  std::size_t failure_budget = 0;
  EvaluationOptions evaluation;
  std::vector<Threshold> thresholds;
  RegressionConfig regression;
  /// `validity_study:` (absolute; empty when not named): a summary.json whose "validity" study the
  /// report consults for sequences without a reference (report/model/validity_support.h).
  std::filesystem::path validity_study;
  std::vector<AlgorithmConfig> algorithms;
  std::vector<SequenceSpec> sequences;
  std::vector<NoiseSpec> noise;
  std::vector<CellFilter> exclude;
  std::vector<CellFilter> include;
};

/// What a sweep file may leave to its caller.
struct SweepConfigContext {
  /// Used when the file has no `catalog:` (the repository's configs/datasets.yaml).
  std::filesystem::path default_catalog;
  /// ${NAME} values for catalog and inline sequence paths, e.g. {"SHARED", "/work/shared"}.
  evaluator::CatalogVariables variables;
  /// What the file may read and run (everything, unless the file was submitted to the service).
  InputPolicy policy;
};

/// Reads and validates a sweep file (format: docs/sweep-files.md). Everything is checked before anything runs:
/// unknown keys at every level, wrong types, missing catalog or sequence files (naming the entry, the
/// file and its download hint), unknown adapters, command argv placeholders, include/exclude names,
/// duplicate names. Errors are InputError "FILE:LINE:COLUMN: field.path: expected ..., got ...".
SweepConfig ReadSweepConfig(const std::filesystem::path& file, const SweepConfigContext& context);

/// The same from text; `file` names it in messages and anchors relative paths (its folder).
SweepConfig ParseSweepConfig(std::string_view yaml_text, const std::filesystem::path& file,
                             const SweepConfigContext& context);

}  // namespace slamsweep::orchestrator::inline config
