#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/statistics/bootstrap.h"

namespace slamsweep::evaluator::inline validity {

/// One run as the validity study reads it (from result.json, the store or the report's model).
struct ValidityRun {
  std::string run_id;
  std::string sequence;
  std::string noise;
  std::string algorithm;
  bool ok = false;
  /// A run that got the reference as odometry measures the answer it was given, not SLAM: left out.
  bool odometry_is_reference = false;
  /// Values by quantity key (ValidityQuantity::key): "<metric>.<statistic>" of the flat metrics
  /// ("corners.value", "ape_trans.rmse") and "wall_s", "cpu_s", "peak_rss_kb" of the resources.
  /// Non-finite values count as absent.
  std::map<std::string, double> values;
};

/// A quantity the study correlates.
struct ValidityQuantity {
  std::string_view key;
  std::string_view title;
  std::string_view unit;
  /// What it is, for the page: "paper map metric", "run resource" or "error against the reference".
  std::string_view kind;
};

/// The ground-truth-free quantities whose trustworthiness is measured: the paper's occupied
/// proportion (its three variants), corners and enclosed areas, and the run's resources (wall
/// time, CPU time, peak memory), which need no ground truth either and are as tempting to read
/// as a sign of trouble.
std::span<const ValidityQuantity> ValidityCandidates();
/// The real errors they are checked against: ATE translation RMSE, the relations translation
/// error (mean), the map-versus-reference Chamfer distance.
std::span<const ValidityQuantity> ValidityTargets();
const ValidityQuantity* FindValidityQuantity(std::string_view key);

/// Which runs one correlation ranks together.
enum class ValidityPooling {
  /// Every run of the sequence ranked together, noise settings mixed: does the metric follow the
  /// error as conditions worsen? Over all sequences: ranks within each sequence, pooled.
  kAcrossNoise,
  /// Ranks within each sequence x noise setting (the runs one report table compares), pooled:
  /// does the metric order runs that are compared with each other?
  kWithinNoise,
};
std::string_view ValidityPoolingName(ValidityPooling pooling);  ///< "across_noise", "within_noise"

enum class ValidityVerdict {
  kTooFewRuns,   ///< fewer than min_runs runs with both values: no number is given
  kNoVariation,  ///< one of the two is constant: rho is undefined
  kTracksError,  ///< the whole interval is above 0: higher value, higher error
  kOpposite,     ///< the whole interval is below 0: higher value, lower error
  kUnclear,      ///< the interval holds 0 (or could not be drawn)
};
std::string_view ValidityVerdictName(ValidityVerdict verdict);  ///< "too few runs", "tracks error", ...

/// One (candidate, target, scope) cell of the study.
struct ValidityCorrelation {
  std::string candidate;
  std::string target;
  /// The sequence, or "" for all sequences together.
  std::string sequence;
  ValidityPooling pooling = ValidityPooling::kAcrossNoise;
  /// Runs with both values that the ranks use (runs alone in their stratum carry no order and
  /// are not counted), and the number of strata they fall into.
  std::size_t runs = 0;
  std::size_t strata = 0;
  std::optional<double> rho;
  std::optional<BootstrapInterval> interval;
  ValidityVerdict verdict = ValidityVerdict::kTooFewRuns;
  /// For a verdict of "tracks error" or "opposite": the Bonferroni interval (confidence 1 - 0.05 / m over the
  /// study's m intervals) and whether it still excludes 0 on the same side. The study reports many intervals;
  /// read alone, some 95 % intervals exclude 0 by chance.
  std::optional<BootstrapInterval> family_interval;
  bool survives_family = false;
};

struct ValidityOptions {
  /// Below this many runs a correlation says "too few runs" instead of a number.
  std::size_t min_runs = 8;
  BootstrapOptions bootstrap;
};

struct ValidityStudy {
  ValidityOptions options;
  /// Sequences where some usable run has a target value, sorted.
  std::vector<std::string> sequences;
  /// Runs used (ok, not odometry = reference) and left out because their odometry was the reference.
  std::size_t runs_used = 0;
  std::size_t runs_odometry_is_reference = 0;
  /// For every target present, every candidate, every sequence that has the target and (with two
  /// such sequences or more) all of them, both poolings; ordered by target, candidate, sequence
  /// ("" last), pooling.
  std::vector<ValidityCorrelation> correlations;
  /// The multiple-comparisons family: how many correlations have an interval, and the confidence each
  /// Bonferroni interval is drawn at (1 - (1 - confidence) / family_size).
  std::size_t family_size = 0;
  double family_confidence = 0.0;

  bool empty() const { return sequences.empty(); }
  const ValidityCorrelation* Find(std::string_view candidate, std::string_view target, std::string_view sequence,
                                  ValidityPooling pooling) const;
};

/// One run's point of a scatter plot: candidate value x, target value y.
struct ValidityPoint {
  double x = 0.0;
  double y = 0.0;
  std::string run_id;
  std::string sequence;
  std::string noise;
  std::string algorithm;
};

/// The usable runs (ok, odometry not the reference) of `sequence` ("" = all) with both values,
/// ordered by run id: what a correlation of the pair rests on and what its plot shows.
std::vector<ValidityPoint> ValidityPoints(std::span<const ValidityRun> runs, std::string_view candidate,
                                          std::string_view target, std::string_view sequence);

/// The study: Spearman's rho of every candidate against every target, per sequence and over all
/// sequences, with both poolings (StratifiedSpearmanRho: ranks are only ever taken among runs of
/// one stratum), each with its stratified percentile bootstrap interval (fixed seed). The result
/// does not depend on the order of `runs` (they are sorted by run id first).
ValidityStudy ComputeValidityStudy(std::vector<ValidityRun> runs, const ValidityOptions& options = {});

/// {"method": {...}, "candidates": [...], "targets": [...], "sequences": [...], "correlations": [...]}:
/// summary.json's "validity".
nlohmann::json ToJson(const ValidityStudy& study);

/// A study back from ToJson (summary.json's "validity"), as a sweep that names another sweep's
/// study reads it: options, sequences, run counts and every correlation with its verdict. Throws
/// InputError naming the field that is missing or of the wrong type.
ValidityStudy ValidityStudyFromJson(const nlohmann::json& json);

}  // namespace slamsweep::evaluator::inline validity
