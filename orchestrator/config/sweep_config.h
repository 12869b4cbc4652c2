#pragma once

// A sweep file, e.g. configs/quickstart.yaml:
//
//   name: quickstart                 # required; [A-Za-z0-9_.-]+
//   output: ../out/quickstart        # default output dir; relative paths are relative to the config file's folder
//                                    #   (default: out/<name> beside the config file)
//   catalog: datasets.yaml           # optional; default: the repository's configs/datasets.yaml (from the caller)
//   iterations: 3                    # >= 1 (default 1)
//   seed: 42                         # base seed (uint64, default 0)
//   seed_policy: per_iteration       # per_iteration (default): DeriveSeed(seed, iteration), so every algorithm
//                                    #   sees the same noisy input in iteration k (a fair comparison);
//                                    # per_run: DeriveSeed(seed ^ Fnv1a64(identity without seed), iteration);
//                                    # fixed: seed for every run
//   workers: 2                       # default --jobs (0 = number of cores)
//   failure_budget: 0                # stop starting new runs after this many failures; 0 = never stop
//   evaluation: {align: se2, rpe_delta_m: 1.0, t_max_diff_s: 0.01, stages: 24, map_resolution_m: 0.05}
//                                    # min_coverage: 0.95 (a run whose trajectory spans less of the reference's
//                                    #   time span fails); map_resolution_m is also the cell size the paper's
//                                    #   map metrics score every map on
//                                    # rpe_segments_m: auto (default: 10-50 % of the reference path, rounded to 1 m,
//                                    #   as KITTI/rpg) or a list such as [5, 10, 20]; [] = no segment RPE
//   validity_study: ../out/validity/summary.json  # optional: the metric validity study of another sweep (its
//                                    #   summary.json), which lets a ground-truth-free map metric be marked best on
//                                    #   sequences without a reference when this sweep's own runs study none
//   regression: {alpha: 0.05, min_effect: 0.2}   # `slamsweep history compare --config`: Mann-Whitney U
//                                    #   significance level in (0, 1) and minimum |Cliff's delta| in [0, 1]
//   thresholds:                      # JUnit failures
//     - {metric: ape_trans, statistic: rmse, max: 1.0}
//   algorithms:
//     - name: icp-slam
//       adapter: mrpt-icp-slam       # mrpt-icp-slam | mrpt-rbpf-slam | command | odometry
//       timeout_s: 120               # default 600
//       memory_limit_mb: 2048        # default 0 = none
//       disk_limit_mb: 4096          # largest file, raw/ in total, private /tmp (default 4096)
//       process_limit: 1024          # processes + threads in the sandbox at once (default 1024)
//       network: false               # true: the host's network (`serve` needs --allow-network)
//       parameters:                  # scalars; a LIST sweeps the parameter (cartesian product over lists)
//         ICP.maxIterations: [40, 80]
//     - name: my-slam                # configs/examples/command-adapter.yaml runs a real one
//       adapter: command             # placeholders: {input} {input_dir} {output_dir} {seed} {seed32} {iteration}
//       {param:NAME} command:
//         argv: [my-slam, --log, "{input}", --out, "{output_dir}", --particles, "{param:particles}"]
//         input_format: carmen       # carmen | rawlog (scans + odometry) | tum (the odometry alone)
//         trajectory: {path: trajectory.tum, format: tum}   # tum | kitti | csv | mrpt | carmen
//         map: {path: map.yaml, format: map_server}     # map_server | mrpt | pgm
//         stage_maps: "stages/*.pgm"
//         stage_unknown_value: 205
//         read_only: [/opt/my-slam/config]  # what else it reads: its sandbox shows these, nothing more
//       parameters: {particles: [30, 60]}
//   sequences:
//     - mrpt-telecom                 # a catalog name
//     - {catalog: intel, name: intel-300, max_scans: 300}   # a catalog entry, renamed and cut
//     - name: floor                  # inline entry: the keys of configs/datasets.yaml entries, plus max_scans
//       format: simulated
//       ground_truth: exact
//       simulation: {...}
//   noise:                           # default: [{name: clean}]
//     - name: clean
//     - name: noisy
//       odometry: {alpha1: 0.01, alpha3: 0.01}     # evaluator OdometryNoiseFromJson fields
//       range: {sigma_m: 0.02}                     # evaluator RangeNoiseFromJson fields
//   exclude:                         # drop cells matching ALL given keys (algorithm, sequence, noise, parameters)
//     - {algorithm: rbpf-slam, sequence: intel-300}
//   include:                         # add cells (algorithm + sequence [+ noise, parameters]) not in the product;
//     - {algorithm: odometry, sequence: fr079, noise: clean}   # no noise = every noise setting
//
// Placeholders of a command's argv: {input}, {output_dir}, {run_dir}, {seed}, {iteration}, {param:NAME}.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/sequence/catalog.h"
#include "orchestrator/config/input_policy.h"
#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator {

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

/// Reads and validates a sweep file (format above). Everything is checked before anything runs:
/// unknown keys at every level, wrong types, missing catalog or sequence files (naming the entry, the
/// file and its download hint), unknown adapters, command argv placeholders, include/exclude names,
/// duplicate names. Errors are InputError "FILE:LINE:COLUMN: field.path: expected ..., got ...".
SweepConfig ReadSweepConfig(const std::filesystem::path& file, const SweepConfigContext& context);

/// The same from text; `file` names it in messages and anchors relative paths (its folder).
SweepConfig ParseSweepConfig(std::string_view yaml_text, const std::filesystem::path& file,
                             const SweepConfigContext& context);

}  // namespace slamsweep::orchestrator
