#include "orchestrator/matrix/expand_matrix.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "evaluator/core/input_error.h"
#include "evaluator/noise/random.h"
#include "orchestrator/matrix/run_id.h"
#include "orchestrator/run/run_json.h"

namespace slamsweep::orchestrator::inline matrix {
namespace {

constexpr std::uint64_t kMaxRuns = 1000000;

/// Every combination of the parameter lists, the first parameter varying slowest (as a reader expects
/// when reading the lists top to bottom).
std::vector<nlohmann::json> ParameterCombinations(const std::vector<ParameterAxis>& axes) {
  std::vector<nlohmann::json> combinations = {nlohmann::json::object()};
  for (const ParameterAxis& axis : axes) {
    std::vector<nlohmann::json> extended;
    extended.reserve(combinations.size() * axis.values.size());
    for (const nlohmann::json& combination : combinations) {
      for (const nlohmann::json& value : axis.values) {
        nlohmann::json next = combination;
        next[axis.name] = value;
        extended.push_back(std::move(next));
      }
    }
    combinations = std::move(extended);
  }
  return combinations;
}

AlgorithmSpec Resolve(const AlgorithmConfig& algorithm, nlohmann::json parameters) {
  AlgorithmSpec spec;
  spec.name = algorithm.name;
  spec.adapter = algorithm.adapter;
  spec.parameters = std::move(parameters);
  spec.timeout_s = algorithm.timeout_s;
  spec.memory_limit_mb = algorithm.memory_limit_mb;
  spec.disk_limit_mb = algorithm.disk_limit_mb;
  spec.process_limit = algorithm.process_limit;
  spec.network = algorithm.network;
  spec.command = algorithm.command;
  return spec;
}

/// Collects runs in order, dropping repeats of a cell and refusing two different cells with one id.
class RunList {
 public:
  void Add(RunSpec spec) {
    const auto [found, inserted] = identities_.emplace(spec.run_id, RunIdentity(spec).dump());
    if (!inserted) {
      if (found->second == RunIdentity(spec).dump()) return;
      throw evaluator::InputError(
          fmt::format("run id {} names two different runs (a 32-bit hash collision); rename one of them", spec.run_id));
    }
    runs_.push_back(std::move(spec));
  }
  std::vector<RunSpec> Take() { return std::move(runs_); }

 private:
  std::vector<RunSpec> runs_;
  std::map<std::string, std::string> identities_;
};

template <typename Item>
const Item& Named(const std::vector<Item>& items, const std::string& name, const std::string& (*name_of)(const Item&)) {
  for (const Item& item : items) {
    if (name_of(item) == name) return item;
  }
  // The config reader checks include/exclude names; reaching this is a bug in the caller's config.
  throw evaluator::InputError("include: unknown name '" + name + "'");
}

const std::string& AlgorithmName(const AlgorithmConfig& algorithm) { return algorithm.name; }
const std::string& SequenceName(const SequenceSpec& sequence) { return sequence.entry.name; }

/// Runs of the product before exclusions and inclusions, saturated at kMaxRuns + 1.
std::uint64_t ProductRuns(const SweepConfig& config) {
  const auto saturating = [](std::uint64_t a, std::uint64_t b) {
    return (a != 0 && b > kMaxRuns / a + 1) ? kMaxRuns + 1 : std::min<std::uint64_t>(a * b, kMaxRuns + 1);
  };
  std::uint64_t product_runs = 0;
  for (const AlgorithmConfig& algorithm : config.algorithms) {
    std::uint64_t combinations = 1;
    for (const ParameterAxis& axis : algorithm.parameters) combinations = saturating(combinations, axis.values.size());
    product_runs = std::min<std::uint64_t>(product_runs + combinations, kMaxRuns + 1);
  }
  product_runs = saturating(product_runs, config.sequences.size());
  product_runs = saturating(product_runs, config.noise.size());
  return saturating(product_runs, static_cast<std::uint64_t>(std::max(config.iterations, 0)));
}

/// A few long parameter lists multiply quickly; refuse before allocating millions of runs.
void CheckSize(const SweepConfig& config) {
  if (ProductRuns(config) > kMaxRuns) {
    throw evaluator::InputError(fmt::format(
        "{}: the sweep expands to more than {} runs (algorithms x parameter combinations x sequences x noise x "
        "iterations); split it or shorten the parameter lists",
        config.source.string(), kMaxRuns));
  }
}

}  // namespace

std::uint64_t SeedForRun(const RunSpec& spec, std::uint64_t base_seed, SeedPolicy policy) {
  const auto iteration = static_cast<std::uint64_t>(spec.iteration);
  switch (policy) {
    case SeedPolicy::kPerIteration:
      return evaluator::DeriveSeed(base_seed, iteration);
    case SeedPolicy::kPerRun: {
      nlohmann::json identity = RunIdentity(spec);
      identity.erase("seed");
      return evaluator::DeriveSeed(base_seed ^ Fnv1a64(identity.dump()), iteration);
    }
    case SeedPolicy::kFixed:
      return base_seed;
  }
  return base_seed;
}

bool Matches(const CellFilter& filter, const RunSpec& spec) {
  if (filter.algorithm && *filter.algorithm != spec.algorithm.name) return false;
  if (filter.sequence && *filter.sequence != spec.sequence.entry.name) return false;
  if (filter.noise && *filter.noise != spec.noise.name) return false;
  for (const auto& [name, value] : filter.parameters.items()) {
    const auto found = spec.algorithm.parameters.find(name);
    if (found == spec.algorithm.parameters.end() || *found != value) return false;
  }
  return true;
}

std::vector<RunSpec> ExpandMatrix(const SweepConfig& config) {
  CheckSize(config);
  RunList runs;
  const auto add_iterations = [&](const AlgorithmSpec& algorithm, const SequenceSpec& sequence, const NoiseSpec& noise,
                                  bool excludable, int iterations) {
    for (int iteration = 0; iteration < iterations; ++iteration) {
      RunSpec spec;
      spec.sweep = config.name;
      spec.algorithm = algorithm;
      spec.sequence = sequence;
      spec.noise = noise;
      spec.iteration = iteration;
      spec.evaluation = config.evaluation;
      for (const Threshold& threshold : config.thresholds) {
        if (ThresholdApplies(threshold, sequence.entry)) spec.thresholds.push_back(threshold);
      }
      if (excludable && std::any_of(config.exclude.begin(), config.exclude.end(),
                                    [&](const CellFilter& filter) { return Matches(filter, spec); })) {
        continue;
      }
      spec.seed = SeedForRun(spec, config.seed, config.seed_policy);
      spec.odometry_is_reference = PlannedOdometryIsReference(sequence.entry, noise);
      spec.run_id = MakeRunId(spec);
      runs.Add(std::move(spec));
    }
  };

  // An algorithm's own iterations are capped by the sweep's (which --iterations may lower).
  const auto iterations_of = [&](const AlgorithmConfig& algorithm) {
    return std::min(algorithm.iterations.value_or(config.iterations), config.iterations);
  };
  for (const AlgorithmConfig& algorithm : config.algorithms) {
    for (const nlohmann::json& parameters : ParameterCombinations(algorithm.parameters)) {
      const AlgorithmSpec resolved = Resolve(algorithm, parameters);
      for (const SequenceSpec& sequence : config.sequences) {
        for (const NoiseSpec& noise : config.noise)
          add_iterations(resolved, sequence, noise, true, iterations_of(algorithm));
      }
    }
  }

  for (const CellFilter& include : config.include) {
    const AlgorithmConfig& algorithm = Named(config.algorithms, *include.algorithm, &AlgorithmName);
    const SequenceSpec& sequence = Named(config.sequences, *include.sequence, &SequenceName);
    std::vector<nlohmann::json> combinations;
    for (nlohmann::json parameters : ParameterCombinations(algorithm.parameters)) {
      parameters.update(include.parameters);
      if (std::find(combinations.begin(), combinations.end(), parameters) == combinations.end()) {
        combinations.push_back(std::move(parameters));
      }
    }
    for (const nlohmann::json& parameters : combinations) {
      const AlgorithmSpec resolved = Resolve(algorithm, parameters);
      for (const NoiseSpec& noise : config.noise) {
        if (include.noise && *include.noise != noise.name) continue;
        add_iterations(resolved, sequence, noise, false, iterations_of(algorithm));
      }
    }
  }
  return runs.Take();
}

std::vector<RunSpec> ExpandMatrix(const SweepConfig& config, std::uint64_t max_runs) {
  const std::uint64_t product_runs = ProductRuns(config);
  if (max_runs < kMaxRuns / 16 && product_runs > 16 * max_runs) {
    throw MatrixTooLargeError(
        fmt::format("{}: the sweep expands to {}{} runs before exclusions; at most {} are "
                    "accepted here: split it or shorten the parameter lists",
                    config.source.string(), product_runs > kMaxRuns ? "more than " : "",
                    std::min(product_runs, kMaxRuns), max_runs));
  }
  std::vector<RunSpec> runs = ExpandMatrix(config);
  if (runs.size() > max_runs) {
    throw MatrixTooLargeError(fmt::format("{}: the sweep has {} runs; at most {} are accepted here: split it",
                                          config.source.string(), runs.size(), max_runs));
  }
  return runs;
}

}  // namespace slamsweep::orchestrator::inline matrix
