#include "cli/sweep_loading.h"

#include <algorithm>
#include <iostream>
#include <set>
#include <thread>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/data_sources.h"
#include "cli/roster_install.h"
#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "orchestrator/adapters/build_stamp.h"
#include "orchestrator/adapters/mrpt_ini.h"
#include "orchestrator/matrix/expand_matrix.h"
#include "orchestrator/matrix/run_id.h"
#include "orchestrator/matrix/shard.h"
#include "orchestrator/store/named_study.h"

namespace slamsweep::cli {

namespace {

/// Throws unless every name in `wanted` is one of `known`.
void RequireKnown(const std::vector<std::string>& wanted, const std::vector<std::string>& known,
                  std::string_view option) {
  for (const std::string& name : wanted) {
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      throw evaluator::InputError(
          fmt::format("{}: no '{}' in the config (it has: {})", option, name, fmt::join(known, ", ")));
    }
  }
}

bool Selected(const std::vector<std::string>& wanted, const std::string& name) {
  return wanted.empty() || std::find(wanted.begin(), wanted.end(), name) != wanted.end();
}

}  // namespace

void AddMatrixSelectionOptions(CLI::App& command, MatrixSelection& selection) {
  command.add_option("--shard", selection.shard, "only share I of N of the matrix (I/N), for several machines");
  command.add_option("--only-algorithms", selection.algorithms, "only these algorithms (comma-separated names)")
      ->delimiter(',');
  command.add_option("--only-sequences", selection.sequences, "only these sequences (comma-separated names)")
      ->delimiter(',');
  command.add_option("--iterations", selection.iterations, "iterations per cell instead of the config's")
      ->check(CLI::PositiveNumber);
}

LoadedSweep LoadSweep(const std::string& config_file, const MatrixSelection& selection, bool install_missing_roster) {
  SweepLimits limits;
  limits.install_missing_roster = install_missing_roster;
  return LoadSweepText(evaluator::ReadTextFile(config_file), config_file, selection, limits);
}

LoadedSweep LoadSweepText(std::string_view text, const std::string& config_file, const MatrixSelection& selection,
                          const SweepLimits& limits) {
  const CatalogLocation location = FindCatalog("");
  orchestrator::SweepConfigContext context;
  context.default_catalog = location.catalog;
  context.variables = {{"SHARED", location.shared_root.string()}};
  context.policy = limits.policy;
  LoadedSweep sweep;
  sweep.config = orchestrator::ParseSweepConfig(text, config_file, context);
  // A named validity study that is not one stops the sweep now, not when its report is written.
  if (!sweep.config.validity_study.empty()) orchestrator::ReadNamedStudy(sweep.config.validity_study);
  sweep.config_hash = fmt::format("{:016x}", orchestrator::Fnv1a64(text));
  std::vector<std::string> algorithms, sequences;
  for (const auto& algorithm : sweep.config.algorithms) algorithms.push_back(algorithm.name);
  for (const auto& sequence : sweep.config.sequences) sequences.push_back(sequence.entry.name);
  RequireKnown(selection.algorithms, algorithms, "--only-algorithms");
  RequireKnown(selection.sequences, sequences, "--only-sequences");
  if (selection.iterations > 0) sweep.config.iterations = selection.iterations;
  std::vector<orchestrator::RunSpec> runs = limits.max_runs > 0
                                                ? orchestrator::ExpandMatrix(sweep.config, limits.max_runs)
                                                : orchestrator::ExpandMatrix(sweep.config);
  for (orchestrator::RunSpec& run : runs) {
    if (Selected(selection.algorithms, run.algorithm.name) && Selected(selection.sequences, run.sequence.entry.name)) {
      sweep.runs.push_back(std::move(run));
    }
  }
  // MRPT parameters must be "SECTION.key": a typo found now, not in every run's log an hour later.
  for (const orchestrator::AlgorithmConfig& algorithm : sweep.config.algorithms) {
    if (!algorithm.adapter.starts_with("mrpt-")) continue;
    for (const orchestrator::RunSpec& run : sweep.runs) {
      if (run.algorithm.name != algorithm.name) continue;
      try {
        orchestrator::IniSettingsFromParameters(run.algorithm.parameters);
      } catch (const evaluator::InputError& error) {
        throw evaluator::InputError(fmt::format("{}: algorithm '{}': {}", config_file, algorithm.name, error.what()));
      }
      break;
    }
  }
  if (!selection.shard.empty()) {
    sweep.runs = orchestrator::SelectShard(std::move(sweep.runs), orchestrator::ParseShard(selection.shard));
  }
  if (limits.install_missing_roster) {
    std::set<std::string> adapters;
    for (const orchestrator::RunSpec& run : sweep.runs) adapters.insert(run.algorithm.adapter);
    InstallMissingRoster(adapters, std::cerr);
  }
  try {
    orchestrator::StampBuildIdentity(sweep.runs);
  } catch (const evaluator::InputError& error) {
    throw evaluator::InputError(fmt::format("{}: {}", config_file, error.what()));
  }
  return sweep;
}

std::size_t DefaultJobs(std::size_t configured) {
  if (configured > 0) return configured;
  const unsigned cores = std::thread::hardware_concurrency();
  return cores > 0 ? cores : 1;
}

}  // namespace slamsweep::cli
