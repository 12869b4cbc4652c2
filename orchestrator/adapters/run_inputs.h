#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/core/relation.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/sequence/robot_log.h"
#include "evaluator/sequence/sequence.h"
#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline adapters {

/// What a run is scored against. Only the worker holds it: adapters get the RobotLog alone, and
/// the worker writes none of it into the run folder before the program has exited.
struct RunTruth {
  std::optional<evaluator::Trajectory> reference;
  /// The relations inside the (cut) log, and how many of the file's were outside it.
  std::optional<evaluator::Relations> relations;
  std::size_t relations_outside_log = 0;
};

/// A run's inputs split by who may see them: `robot` is what the program is given (scans and
/// odometry after cutting and noise), `truth` what only scoring uses (noise-free).
struct RunInputs {
  evaluator::RobotLog robot;
  RunTruth truth;
  /// What the sequence reader repaired or assumed (each naming the file), for result.json.
  std::vector<std::string> warnings;
  /// The noise applied and its seeds, recorded in result.json so the input can be reproduced.
  nlohmann::json noise_record;
  /// What the sequence is like (result.json "sequence"): "scans" and "span_s" (first to last scan: the
  /// report takes the densest of several logs of one run), "stamps" (evaluator StampFactsJson) when the
  /// reader records how it chose them, and "scan_spacing" (ScanSpacingJson) with two scans or more, measured
  /// after cutting and before noise (the data's density, not the noise's).
  nlohmann::json sequence_record = nlohmann::json::object();
  /// The program's odometry equals the reference at every scan (a corrected log without odometry
  /// noise): the run measures an upper bound, not SLAM (OdometryIsReference).
  bool odometry_is_reference = false;
};

/// The words the report, summary and warnings use for a run whose odometry is the reference.
inline constexpr std::string_view kOdometryIsReferenceWarning =
    "odometry = reference: an upper bound, not a SLAM result (the program's odometry is the reference "
    "trajectory; add odometry noise to make it a SLAM test)";

/// The first `max_scans` scans of `sequence` with their odometry (evaluator KeepScanRange); reference poses
/// later than the last kept scan are dropped too, and relations there count as outside the log (they
/// describe a part the run never saw).
/// A sequence with fewer scans is returned unchanged; max_scans = 0 is an InputError.
evaluator::Sequence CutSequence(evaluator::Sequence sequence, std::size_t max_scans);

/// Applies the run's noise exactly as `slamsweep data convert` does: odometry noise with
/// DeriveSeed(seed, 0), drawn around the reference when it has a pose at every scan (corrected
/// logs, whose odometry equals their reference), else around the odometry; range noise with
/// DeriveSeed(seed, 1). Returns the record of what was applied.
nlohmann::json ApplyRunNoise(evaluator::Sequence& sequence, const NoiseSpec& noise, std::uint64_t seed);

/// Whether the odometry is the reference: the reference has a pose at every scan's stamp and each
/// equals the odometry pose there (within 1 um and 1 urad). Then a SLAM program is handed the answer.
bool OdometryIsReference(const evaluator::Sequence& sequence);

/// The run's sequence as the program's input starts from: loaded (LoadCatalogSequence: paths in run.json
/// are already resolved), cut to max_scans and validated; no noise yet.
evaluator::Sequence LoadRunSequence(const RunSpec& spec);

/// Loads the run's sequence (LoadCatalogSequence: paths in run.json are already resolved), cuts
/// and noises it, and splits it into the program's part and the truth. With a `cache_dir`
/// (PreparedInputCacheDir), the sequence read, cut and checked is taken from the sweep's cache of
/// prepared inputs (orchestrator/input_cache), made there by the first run that needs it; noise is
/// always the run's own. Every problem is an InputError naming the sequence or the field.
RunInputs PrepareRunInputs(const RunSpec& spec, const std::filesystem::path& cache_dir = {});

}  // namespace slamsweep::orchestrator::inline adapters
