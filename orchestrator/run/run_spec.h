#pragma once

#include <cstdint>
#include <map>
#include <string_view>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/noise/odometry_noise.h"
#include "evaluator/noise/range_noise.h"
#include "evaluator/catalog/catalog.h"

namespace slamsweep::orchestrator::inline run {

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
/// {input} (the robot log written in `input_format`), {input_dir}, {output_dir} (the run's raw/
/// folder, the program's working directory), {seed}, {seed32}, {iteration}, {param:NAME}
/// (config/placeholders.h).
struct CommandDeclaration {
  std::vector<std::string> argv;
  /// "rawlog", "carmen" or "tum" (SequenceWriteFormat names; "tum" is the odometry alone).
  std::string input_format = "carmen";
  std::optional<DeclaredOutput> trajectory;
  std::optional<DeclaredOutput> map;
  /// Glob relative to raw/ (e.g. "stages/*.pgm"); matches are taken in lexicographic order.
  std::string stage_maps_glob;
  /// Format of the stage maps: "pgm"/"png" images (0 occupied .. 255 free, `unknown_value` unknown).
  int stage_unknown_value = 205;
  /// Absolute folders and files the program reads besides {input} (its data, configuration,
  /// libraries outside /usr): the only other paths its sandbox shows, read-only.
  std::vector<std::string> read_only;
  bool operator==(const CommandDeclaration&) const = default;
};

/// Default of an algorithm's `disk_limit_mb`: the largest file its program may write, the most its
/// raw/ folder may hold and the size of its private /tmp.
inline constexpr std::uint64_t kDefaultDiskLimitMb = 4096;
/// Default of an algorithm's `process_limit`: processes and threads its sandbox may hold at once.
inline constexpr std::uint64_t kDefaultProcessLimit = 1024;
/// Fewer could not hold the sandbox's process 1 and a program with a thread or two.
inline constexpr std::uint64_t kMinProcessLimit = 4;

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
  /// The sandbox's limits (orchestrator/sandbox): a file and raw/ at most this size, /tmp as large.
  std::uint64_t disk_limit_mb = kDefaultDiskLimitMb;
  std::uint64_t process_limit = kDefaultProcessLimit;
  /// The program may use the host's network (else only a loopback of its own).
  bool network = false;
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
  /// The canvas rule of the map metrics (spec/metrics.md): crop to the known cells first. false gives
  /// the raw-grid profile, which depends on each program's canvas size.
  bool crop = true;
  /// A run whose trajectory spans less than this fraction of the reference's time span fails
  /// (evaluator/trajectory_metrics/coverage.h): its errors would be measured on the part it chose to keep.
  double min_coverage = 0.95;
  /// Segment lengths of the segment RPE (evaluator SegmentRpe), ascending. Absent ("auto"): 10, 20,
  /// 30, 40 and 50 % of the sequence's whole reference path rounded to 1 m, the same for every run
  /// of a sequence, so the runs of a group are scored on the same segments. Empty: no segment RPE.
  std::optional<std::vector<double>> rpe_segments_m;
  bool operator==(const EvaluationOptions&) const = default;
};

/// A metric limit: a run whose metric statistic exceeds `max` (or falls below `min`) fails in JUnit,
/// and so does a run that lacks the metric.
struct Threshold {
  std::string metric;
  std::string statistic = "rmse";
  std::optional<double> max;
  std::optional<double> min;
};

/// Whether a sweep's threshold is one the runs of `entry` can be held to: a metric that needs a
/// reference trajectory (ape_, rpe_, segment_), relations (relations_) or a reference map (map_)
/// applies only to sequences that have it; the ground-truth-free metrics apply everywhere.
bool ThresholdApplies(const Threshold& threshold, const evaluator::CatalogEntry& entry);

/// What a run's result depends on besides its inputs: the slamsweep that computed it and the
/// program files it executed or read as configuration. Not part of the run id (the id names the
/// experiment); the rerun-skip check reuses a finished run only when this is unchanged.
struct BuildIdentity {
  /// SlamsweepRevision() of the planning slamsweep.
  std::string slamsweep_revision;
  /// Absolute path -> SHA-256 of every program file (binary, wrapper script, config template).
  std::map<std::string, std::string> program_files;
  bool operator==(const BuildIdentity&) const = default;
};

/// A short name of a build identity ("b" and 12 hex digits of a hash of the slamsweep revision and
/// the program files' digests, not their paths): equal for the same binaries wherever they were
/// unpacked, different for a rebuilt program. Results of different signatures are never pooled.
std::string BuildSignature(const BuildIdentity& build);

/// Whether a run can be reproduced from its seed.
enum class Seeding {
  kSeeded,         ///< the run's seed reaches the program's random generator
  kDeterministic,  ///< the program draws no random number: the same input gives the same result
  kUnseeded,       ///< the program is randomised and takes no seed: reruns differ
};

/// "seeded", "deterministic", "unseeded".
std::string_view SeedingName(Seeding seeding);

/// Runs are averaged, compared and ranked only within one group: the same sequence, algorithm,
/// parameter values and noise setting. Runs that differ in any of these never share a mean, a
/// "best" mark or a history series.
struct ComparisonGroup {
  std::string sequence;
  std::string algorithm;
  /// Every parameter as "name=value", sorted by name, joined by ';' (ParametersText); "" for none.
  std::string parameters;
  std::string noise;
  /// "recorded" or "reference" (OdometryModeOf): runs on a log's recorded odometry and runs handed
  /// its reference never share a group.
  std::string odometry = "recorded";
  auto operator<=>(const ComparisonGroup&) const = default;
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
  /// Set after expansion (StampBuildIdentity in orchestrator/adapters), from the program files.
  BuildIdentity build;
  /// From the adapter (and a command's use of {seed}/{seed32}), set with `build`.
  Seeding seeding = Seeding::kUnseeded;
  /// The sequence's odometry is its reference and no odometry noise is applied (a corrected log,
  /// clean): the program is handed the answer, so the run is an upper bound, not a SLAM result.
  bool odometry_is_reference = false;
  /// The sweep was told --allow-unisolated: where no sandbox can be made, the program runs without
  /// one (its result marked "unisolated") instead of the run failing.
  bool allow_unisolated = false;
};

/// "name=value;..." of scalar parameters, sorted by name (nlohmann's object order); text values as
/// they are, numbers and booleans as JSON writes them.
std::string ParametersText(const nlohmann::json& parameters);

/// "name" or, when the run has parameters, "name [k=v;...]": the row of a comparison, as JUnit test
/// names and history series show it.
std::string AlgorithmLabel(const std::string& algorithm, const std::string& parameters_text);

/// The group a run belongs to (ComparisonGroup).
ComparisonGroup ComparisonGroupOf(const RunSpec& spec);

/// The odometry mode a sequence's runs use ("recorded", "reference"; EffectiveOdometryMode).
std::string OdometryModeOf(const SequenceSpec& sequence);

/// Whether the odometry a run's program gets is the reference: a corrected CARMEN log in reference
/// odometry mode whose odometry noise is absent or zero. The worker checks the same on the data (OdometryIsReference).
bool PlannedOdometryIsReference(const evaluator::CatalogEntry& entry, const NoiseSpec& noise);

}  // namespace slamsweep::orchestrator::inline run
