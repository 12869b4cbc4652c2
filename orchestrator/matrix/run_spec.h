#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/noise/odometry_noise.h"
#include "evaluator/noise/range_noise.h"
#include "evaluator/sequence/catalog.h"

namespace slamsweep::orchestrator {

/// What a generic command adapter declares about one output file of the program.
struct DeclaredOutput {
  /// Relative to the run's raw/ folder (the program's output directory); may hold placeholders.
  std::string path;
  /// Trajectories: "tum", "kitti", "csv", "mrpt", "carmen". Maps: "map_server", "mrpt", "pgm".
  std::string format;
  bool operator==(const DeclaredOutput&) const = default;
};

/// A SLAM program run through a declared argv template (adapter "command"). Never a shell:
/// each element of `argv` becomes exactly one argument after its placeholders are replaced:
/// {input} (the sequence written in `input_format`), {output_dir} (the run's raw/ folder),
/// {run_dir}, {seed}, {iteration}, {param:NAME} (a parameter's value).
struct CommandDeclaration {
  std::vector<std::string> argv;
  /// "rawlog", "carmen" or "tum" (SequenceWriteFormat names).
  std::string input_format = "carmen";
  std::optional<DeclaredOutput> trajectory;
  std::optional<DeclaredOutput> map;
  /// Glob relative to raw/ (e.g. "stages/*.pgm"); matches are taken in lexicographic order.
  std::string stage_maps_glob;
  /// Format of the stage maps: "pgm"/"png" images (0 occupied .. 255 free, `unknown_value` unknown).
  int stage_unknown_value = 205;
  bool operator==(const CommandDeclaration&) const = default;
};

/// One algorithm with every parameter resolved to a single value.
struct AlgorithmSpec {
  std::string name;
  /// "mrpt-icp-slam", "mrpt-rbpf-slam", "command" or "odometry".
  std::string adapter;
  /// Parameter name -> scalar value (number, string or bool).
  nlohmann::json parameters = nlohmann::json::object();
  double timeout_s = 600.0;
  /// 0 = no limit.
  std::uint64_t memory_limit_mb = 0;
  std::optional<CommandDeclaration> command;
};

/// A sequence as the worker needs it: a catalog entry with every path resolved, optionally cut.
struct SequenceSpec {
  evaluator::CatalogEntry entry;
  /// Keep only the first N scans (a quick variant of a long log); empty = all.
  std::optional<std::size_t> max_scans;
};

/// A named noise setting of a noise sweep; both empty = the sequence as recorded ("clean").
struct NoiseSpec {
  std::string name = "clean";
  std::optional<evaluator::OdometryNoise> odometry;
  std::optional<evaluator::RangeNoise> range;
};

/// How the worker scores a run (the sweep's `evaluation:` block).
struct EvaluationOptions {
  /// APE alignment: none, origin, se2, se3, sim2, sim3.
  std::string align = "se2";
  double rpe_delta_m = 1.0;
  double t_max_diff_s = 0.01;
  /// Stage maps rendered when the program writes none (odometry baseline, trajectory-only programs).
  std::size_t stages = 24;
  /// Cell size of maps rendered from trajectories.
  double map_resolution_m = 0.05;
};

/// A metric limit: a run whose metric statistic exceeds `max` (or falls below `min`) fails in JUnit.
struct Threshold {
  std::string metric;
  std::string statistic = "rmse";
  std::optional<double> max;
  std::optional<double> min;
};

/// One cell of the matrix, fully resolved: everything a worker needs, nothing it must look up.
struct RunSpec {
  std::string run_id;
  std::string sweep;
  AlgorithmSpec algorithm;
  SequenceSpec sequence;
  NoiseSpec noise;
  int iteration = 0;
  std::uint64_t seed = 0;
  EvaluationOptions evaluation;
  std::vector<Threshold> thresholds;
};

/// run.json, as in orchestrator/DESIGN.md. FromJson is strict: an unknown or mistyped field is an
/// InputError naming its path ("run.json: algorithm.timeout_s: expected a number").
nlohmann::json ToJson(const RunSpec& spec);
RunSpec RunSpecFromJson(const nlohmann::json& json);

nlohmann::json ToJson(const evaluator::CatalogEntry& entry);
evaluator::CatalogEntry CatalogEntryFromJson(const nlohmann::json& json, const std::string& path = "sequence");

/// The revision of a built-in adapter's own settings (1 for adapters that never changed them, and
/// for unknown names). Part of the run identity from 2 on: results of an adapter whose defaults
/// changed are not reused by a re-run into the same output folder.
int AdapterRevision(const std::string& adapter);

/// The part of a run that decides its result (algorithm, sequence, noise, iteration, seed) as
/// canonical JSON; its hash names the run, so an unchanged run keeps its id across sweeps.
/// The sequence's citation, licence and download texts are left out: they do not change a result.
nlohmann::json RunIdentity(const RunSpec& spec);

}  // namespace slamsweep::orchestrator
