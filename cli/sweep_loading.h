#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "orchestrator/config/sweep_config.h"
#include "orchestrator/run/run_spec.h"

namespace slamsweep::cli {

/// A sweep file read, validated and expanded, as `run` and `plan` both need it.
struct LoadedSweep {
  orchestrator::SweepConfig config;
  /// The matrix, or the share of it that `--shard I/N` selects.
  std::vector<orchestrator::RunSpec> runs;
  /// FNV-1a of the file's bytes (hex), recorded with each sweep to tell edited configs apart.
  std::string config_hash;
};

/// Which part of a sweep to run: the flags `run` and `plan` share (Jenkins job parameters map onto them).
struct MatrixSelection {
  /// --shard I/N; empty = all runs.
  std::string shard;
  /// --only-algorithms / --only-sequences: names from the config; empty = all.
  std::vector<std::string> algorithms;
  std::vector<std::string> sequences;
  /// --iterations: overrides the config's count (0 = keep). Iteration k keeps its seed and run id
  /// whatever the count, so a shorter sweep is a prefix of the longer one and shares its results.
  int iterations = 0;
};

/// Adds --shard, --only-algorithms, --only-sequences and --iterations to `command`.
void AddMatrixSelectionOptions(CLI::App& command, MatrixSelection& selection);

/// Reads `config_file` with the catalog and ${SHARED} of FindCatalog(""), expands it and keeps the
/// selected runs. Throws InputError (file:line:column) for a bad config, and naming the option and
/// the config's names for an unknown algorithm or sequence.
/// With `install_missing_roster` (plan and run, never the service or workers), the roster algorithms the
/// selected runs need are built first when missing (InstallMissingRoster, cli/roster_install.h).
LoadedSweep LoadSweep(const std::string& config_file, const MatrixSelection& selection,
                      bool install_missing_roster = false);

/// What a sweep from someone the operator does not fully trust may ask for (`slamsweep serve`).
struct SweepLimits {
  /// Readable roots and whether `adapter: command` is allowed (PolicyError otherwise).
  orchestrator::InputPolicy policy;
  /// Most runs accepted (MatrixTooLargeError beyond); 0 = the matrix's own limit.
  std::uint64_t max_runs = 0;
  /// Build the missing roster algorithms of the selected runs before stamping them (LoadSweep).
  bool install_missing_roster = false;
};

/// LoadSweep of a sweep file's text: `config_file` names it in messages and anchors its relative paths.
LoadedSweep LoadSweepText(std::string_view text, const std::string& config_file, const MatrixSelection& selection,
                          const SweepLimits& limits);

/// Runs at once: `configured` when > 0, else the number of cores.
std::size_t DefaultJobs(std::size_t configured);

}  // namespace slamsweep::cli
