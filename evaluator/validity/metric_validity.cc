#include "evaluator/validity/metric_validity.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <set>
#include <thread>
#include <tuple>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline validity {
namespace {

constexpr std::array<ValidityQuantity, 8> kCandidates = {{
    {"occupied_to_free_unknown.value", "Occupied proportion (occupied / free+unknown)", "ratio", "paper map metric"},
    {"occupied_to_all.value", "Occupied / all cells", "ratio", "paper map metric"},
    {"unknown_to_all.value", "Unknown / all cells", "ratio", "paper map metric"},
    {"corners.value", "Corners", "count", "paper map metric"},
    {"enclosed_areas.value", "Enclosed areas", "count", "paper map metric"},
    {"wall_s", "Wall time", "s", "run resource"},
    {"cpu_s", "CPU time", "s", "run resource"},
    {"peak_rss_kb", "Peak memory (RSS)", "kB", "run resource"},
}};

constexpr std::array<ValidityQuantity, 3> kTargets = {{
    {"ape_trans.rmse", "ATE translation RMSE", "m", "error against the reference"},
    {"relations_trans.mean", "Relations translation error (mean)", "m", "error against the reference"},
    {"map_chamfer.value", "Map vs reference: Chamfer distance", "m", "error against the reference"},
}};

std::optional<double> ValueOf(const ValidityRun& run, std::string_view key) {
  const auto it = run.values.find(std::string(key));
  if (it == run.values.end() || !std::isfinite(it->second)) return std::nullopt;
  return it->second;
}

bool Usable(const ValidityRun& run) { return run.ok && !run.odometry_is_reference; }

ValidityVerdict VerdictOf(const ValidityCorrelation& correlation) {
  if (!correlation.rho) return ValidityVerdict::kNoVariation;
  if (!correlation.interval) return ValidityVerdict::kUnclear;
  if (correlation.interval->low > 0.0) return ValidityVerdict::kTracksError;
  if (correlation.interval->high < 0.0) return ValidityVerdict::kOpposite;
  return ValidityVerdict::kUnclear;
}

/// The correlation of one pair over `points` (all of one scope), ranked within strata. A decided verdict's
/// bootstrap replicates go to `decided_replicates`: the family interval is their wider percentiles.
ValidityCorrelation Correlate(const std::vector<ValidityPoint>& points, ValidityPooling pooling, bool all_sequences,
                              const ValidityOptions& options, BootstrapReplicates& decided_replicates) {
  // Strata: the sequence (over all sequences, across noise), the sequence x noise (within noise),
  // or nothing (one sequence, across noise). Ids follow the sorted stratum names.
  std::map<std::pair<std::string, std::string>, std::size_t> stratum_ids;
  const auto key_of = [&](const ValidityPoint& point) {
    return std::pair{all_sequences || pooling == ValidityPooling::kWithinNoise ? point.sequence : std::string(),
                     pooling == ValidityPooling::kWithinNoise ? point.noise : std::string()};
  };
  for (const ValidityPoint& point : points) stratum_ids.emplace(key_of(point), 0);
  std::size_t next = 0;
  for (auto& [key, id] : stratum_ids) id = next++;
  std::vector<PairedStratum> strata(stratum_ids.size());
  for (const ValidityPoint& point : points) {
    PairedStratum& stratum = strata[stratum_ids.at(key_of(point))];
    stratum.x.push_back(point.x);
    stratum.y.push_back(point.y);
  }
  ValidityCorrelation correlation;
  correlation.pooling = pooling;
  for (const PairedStratum& stratum : strata) {
    if (stratum.x.size() < 2) continue;
    correlation.runs += stratum.x.size();
    ++correlation.strata;
  }
  if (correlation.runs < options.min_runs) {
    correlation.verdict = ValidityVerdict::kTooFewRuns;
    return correlation;
  }
  correlation.rho = PooledRankCorrelation(strata);
  std::optional<BootstrapReplicates> replicates;
  if (correlation.rho) replicates = PooledRankCorrelationReplicates(strata, options.bootstrap);
  if (replicates) {
    correlation.interval =
        PercentileInterval(*replicates, options.bootstrap.confidence, options.bootstrap.min_defined_fraction);
  }
  correlation.verdict = VerdictOf(correlation);
  const bool decided =
      correlation.verdict == ValidityVerdict::kTracksError || correlation.verdict == ValidityVerdict::kOpposite;
  if (decided && replicates) decided_replicates = std::move(*replicates);
  return correlation;
}

nlohmann::json OptionalNumber(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json();
}

nlohmann::json QuantitiesJson(std::span<const ValidityQuantity> quantities) {
  nlohmann::json out = nlohmann::json::array();
  for (const ValidityQuantity& q : quantities) {
    out.push_back({{"key", q.key}, {"title", q.title}, {"unit", q.unit}, {"kind", q.kind}});
  }
  return out;
}

}  // namespace

std::span<const ValidityQuantity> ValidityCandidates() { return kCandidates; }
std::span<const ValidityQuantity> ValidityTargets() { return kTargets; }

const ValidityQuantity* FindValidityQuantity(std::string_view key) {
  for (std::span<const ValidityQuantity> list : {ValidityCandidates(), ValidityTargets()}) {
    for (const ValidityQuantity& quantity : list) {
      if (quantity.key == key) return &quantity;
    }
  }
  return nullptr;
}

std::string_view ValidityPoolingName(ValidityPooling pooling) {
  return pooling == ValidityPooling::kAcrossNoise ? "across_noise" : "within_noise";
}

std::string_view ValidityVerdictName(ValidityVerdict verdict) {
  switch (verdict) {
    case ValidityVerdict::kTooFewRuns:
      return "too few runs";
    case ValidityVerdict::kNoVariation:
      return "no variation";
    case ValidityVerdict::kTracksError:
      return "tracks error";
    case ValidityVerdict::kOpposite:
      return "opposite";
    case ValidityVerdict::kUnclear:
      return "unclear";
  }
  return "unclear";
}

const ValidityCorrelation* ValidityStudy::Find(std::string_view candidate, std::string_view target,
                                               std::string_view sequence, ValidityPooling pooling) const {
  for (const ValidityCorrelation& c : correlations) {
    if (c.candidate == candidate && c.target == target && c.sequence == sequence && c.pooling == pooling) return &c;
  }
  return nullptr;
}

std::vector<ValidityPoint> ValidityPoints(std::span<const ValidityRun> runs, std::string_view candidate,
                                          std::string_view target, std::string_view sequence) {
  std::vector<ValidityPoint> points;
  for (const ValidityRun& run : runs) {
    if (!Usable(run) || (!sequence.empty() && run.sequence != sequence)) continue;
    const std::optional<double> x = ValueOf(run, candidate), y = ValueOf(run, target);
    if (x && y) points.push_back({*x, *y, run.run_id, run.sequence, run.noise, run.algorithm});
  }
  std::sort(points.begin(), points.end(),
            [](const ValidityPoint& a, const ValidityPoint& b) { return a.run_id < b.run_id; });
  return points;
}

ValidityStudy ComputeValidityStudy(std::vector<ValidityRun> runs, const ValidityOptions& options) {
  std::sort(runs.begin(), runs.end(), [](const ValidityRun& a, const ValidityRun& b) { return a.run_id < b.run_id; });
  ValidityStudy study;
  study.options = options;
  std::set<std::string> sequences;
  std::map<std::string_view, std::set<std::string>> sequences_of_target;
  for (const ValidityRun& run : runs) {
    if (run.ok && run.odometry_is_reference) ++study.runs_odometry_is_reference;
    if (!Usable(run)) continue;
    ++study.runs_used;
    for (const ValidityQuantity& target : kTargets) {
      if (ValueOf(run, target.key)) {
        sequences.insert(run.sequence);
        sequences_of_target[target.key].insert(run.sequence);
      }
    }
  }
  study.sequences.assign(sequences.begin(), sequences.end());
  struct CorrelationTask {
    std::shared_ptr<const std::vector<ValidityPoint>> points;
    ValidityPooling pooling;
    std::string candidate;
    std::string target;
    std::string sequence;
  };
  std::vector<CorrelationTask> tasks;
  for (const ValidityQuantity& target : kTargets) {
    const auto present = sequences_of_target.find(target.key);
    if (present == sequences_of_target.end()) continue;
    // The sequences with this error (relations exist for few), then all of them together.
    std::vector<std::string> scopes(present->second.begin(), present->second.end());
    if (scopes.size() >= 2) scopes.push_back("");
    for (const ValidityQuantity& candidate : kCandidates) {
      for (const std::string& sequence : scopes) {
        auto points = std::make_shared<const std::vector<ValidityPoint>>(
            ValidityPoints(runs, candidate.key, target.key, sequence));
        for (ValidityPooling pooling : {ValidityPooling::kAcrossNoise, ValidityPooling::kWithinNoise}) {
          tasks.push_back({points, pooling, std::string(candidate.key), std::string(target.key), sequence});
        }
      }
    }
  }
  // Each correlation draws its own bootstrap from the fixed seed: computed on several threads, the study
  // is the same as computed in order, and a sweep of 10,000 runs waits for it half as long on 2 cores.
  study.correlations.resize(tasks.size());
  std::vector<BootstrapReplicates> decided_replicates(tasks.size());
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t i = next++; i < tasks.size(); i = next++) {
      const CorrelationTask& task = tasks[i];
      ValidityCorrelation correlation =
          Correlate(*task.points, task.pooling, task.sequence.empty(), options, decided_replicates[i]);
      correlation.candidate = task.candidate;
      correlation.target = task.target;
      correlation.sequence = task.sequence;
      study.correlations[i] = std::move(correlation);
    }
  };
  {
    std::vector<std::jthread> helpers;
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    for (unsigned t = 1; t < threads && t < tasks.size(); ++t) helpers.emplace_back(work);
    work();
  }
  // Bonferroni over the study's intervals: only a decided verdict can fail to survive, so only those get the
  // wider percentiles of the same resamples (the same seed would draw them again).
  for (const ValidityCorrelation& c : study.correlations) study.family_size += c.interval ? 1 : 0;
  if (study.family_size == 0) return study;
  study.family_confidence = 1.0 - (1.0 - options.bootstrap.confidence) / static_cast<double>(study.family_size);
  for (std::size_t i = 0; i < study.correlations.size(); ++i) {
    ValidityCorrelation& c = study.correlations[i];
    if (c.verdict != ValidityVerdict::kTracksError && c.verdict != ValidityVerdict::kOpposite) continue;
    c.family_interval =
        PercentileInterval(decided_replicates[i], study.family_confidence, options.bootstrap.min_defined_fraction);
    c.survives_family =
        c.family_interval &&
        (c.verdict == ValidityVerdict::kTracksError ? c.family_interval->low > 0.0 : c.family_interval->high < 0.0);
  }
  return study;
}

nlohmann::json ToJson(const ValidityStudy& study) {
  nlohmann::json correlations = nlohmann::json::array();
  for (const ValidityCorrelation& c : study.correlations) {
    correlations.push_back({{"candidate", c.candidate},
                            {"target", c.target},
                            {"sequence", c.sequence.empty() ? nlohmann::json() : nlohmann::json(c.sequence)},
                            {"pooling", ValidityPoolingName(c.pooling)},
                            {"runs", c.runs},
                            {"strata", c.strata},
                            {"spearman_rho", OptionalNumber(c.rho)},
                            {"ci_low", c.interval ? nlohmann::json(c.interval->low) : nlohmann::json()},
                            {"ci_high", c.interval ? nlohmann::json(c.interval->high) : nlohmann::json()},
                            {"resamples_defined", c.interval ? nlohmann::json(c.interval->defined) : nlohmann::json()},
                            {"verdict", ValidityVerdictName(c.verdict)}});
    if (c.family_interval) {
      correlations.back()["ci_low_bonferroni"] = c.family_interval->low;
      correlations.back()["ci_high_bonferroni"] = c.family_interval->high;
      correlations.back()["survives_bonferroni"] = c.survives_family;
    }
  }
  return {{"method",
           {{"statistic",
             "Spearman's rank correlation (average ranks for ties); over several strata, the Pearson "
             "correlation of within-stratum ranks centred on the stratum's mean rank and divided by its size"},
            {"interval", "percentile bootstrap, resampling runs with replacement within each stratum"},
            {"confidence", study.options.bootstrap.confidence},
            {"resamples", study.options.bootstrap.resamples},
            {"seed", study.options.bootstrap.seed},
            {"min_runs", study.options.min_runs},
            {"runs", "successful runs whose odometry was not the reference"},
            {"across_noise", "strata: none for one sequence, the sequence for all sequences"},
            {"within_noise", "strata: sequence x noise setting"},
            {"multiple_comparisons",
             {{"method", "Bonferroni: each decided verdict's interval redrawn at 1 - (1 - confidence) / family_size"},
              {"family_size", study.family_size},
              {"confidence", study.family_confidence}}}}},
          {"candidates", QuantitiesJson(ValidityCandidates())},
          {"targets", QuantitiesJson(ValidityTargets())},
          {"sequences", study.sequences},
          {"runs_used", study.runs_used},
          {"runs_odometry_is_reference", study.runs_odometry_is_reference},
          {"correlations", std::move(correlations)}};
}

namespace {

const nlohmann::json& Field(const nlohmann::json& object, const char* key, const std::string& where) {
  if (!object.is_object() || !object.contains(key)) throw InputError(where + ": missing \"" + key + "\"");
  return object.at(key);
}

template <typename T>
T FieldAs(const nlohmann::json& object, const char* key, const std::string& where) {
  try {
    return Field(object, key, where).get<T>();
  } catch (const nlohmann::json::exception&) {
    throw InputError(where + "." + key + ": wrong type");
  }
}

std::optional<double> OptionalField(const nlohmann::json& object, const char* key, const std::string& where) {
  const nlohmann::json& value = Field(object, key, where);
  if (value.is_null()) return std::nullopt;
  if (!value.is_number()) throw InputError(where + "." + key + ": expected a number or null");
  return value.get<double>();
}

}  // namespace

ValidityStudy ValidityStudyFromJson(const nlohmann::json& json) {
  ValidityStudy study;
  const std::string where = "validity";
  const nlohmann::json& method = Field(json, "method", where);
  study.options.bootstrap.confidence = FieldAs<double>(method, "confidence", where + ".method");
  study.options.bootstrap.resamples = FieldAs<std::size_t>(method, "resamples", where + ".method");
  study.options.bootstrap.seed = FieldAs<std::uint64_t>(method, "seed", where + ".method");
  study.options.min_runs = FieldAs<std::size_t>(method, "min_runs", where + ".method");
  if (method.contains("multiple_comparisons")) {
    const nlohmann::json& family = Field(method, "multiple_comparisons", where + ".method");
    study.family_size = FieldAs<std::size_t>(family, "family_size", where + ".method.multiple_comparisons");
    study.family_confidence = FieldAs<double>(family, "confidence", where + ".method.multiple_comparisons");
  }
  study.sequences = FieldAs<std::vector<std::string>>(json, "sequences", where);
  study.runs_used = FieldAs<std::size_t>(json, "runs_used", where);
  study.runs_odometry_is_reference = FieldAs<std::size_t>(json, "runs_odometry_is_reference", where);
  const nlohmann::json& correlations = Field(json, "correlations", where);
  if (!correlations.is_array()) throw InputError(where + ".correlations: expected an array");
  for (std::size_t i = 0; i < correlations.size(); ++i) {
    const nlohmann::json& entry = correlations[i];
    const std::string at = where + ".correlations[" + std::to_string(i) + "]";
    ValidityCorrelation c;
    c.candidate = FieldAs<std::string>(entry, "candidate", at);
    c.target = FieldAs<std::string>(entry, "target", at);
    const nlohmann::json& sequence = Field(entry, "sequence", at);
    c.sequence = sequence.is_null() ? std::string() : FieldAs<std::string>(entry, "sequence", at);
    const std::string pooling = FieldAs<std::string>(entry, "pooling", at);
    if (pooling == ValidityPoolingName(ValidityPooling::kAcrossNoise)) {
      c.pooling = ValidityPooling::kAcrossNoise;
    } else if (pooling == ValidityPoolingName(ValidityPooling::kWithinNoise)) {
      c.pooling = ValidityPooling::kWithinNoise;
    } else {
      throw InputError(at + ".pooling: expected across_noise or within_noise, got \"" + pooling + "\"");
    }
    c.runs = FieldAs<std::size_t>(entry, "runs", at);
    c.strata = FieldAs<std::size_t>(entry, "strata", at);
    c.rho = OptionalField(entry, "spearman_rho", at);
    const std::optional<double> low = OptionalField(entry, "ci_low", at), high = OptionalField(entry, "ci_high", at);
    if (low && high) {
      BootstrapInterval interval;
      interval.low = *low;
      interval.high = *high;
      interval.resamples = study.options.bootstrap.resamples;
      interval.defined = FieldAs<std::size_t>(entry, "resamples_defined", at);
      c.interval = interval;
    }
    const std::string verdict = FieldAs<std::string>(entry, "verdict", at);
    bool known = false;
    for (ValidityVerdict v : {ValidityVerdict::kTooFewRuns, ValidityVerdict::kNoVariation,
                              ValidityVerdict::kTracksError, ValidityVerdict::kOpposite, ValidityVerdict::kUnclear}) {
      if (verdict == ValidityVerdictName(v)) {
        c.verdict = v;
        known = true;
      }
    }
    if (!known) throw InputError(at + ".verdict: unknown verdict \"" + verdict + "\"");
    // The Bonferroni interval of a decided verdict; optional, so that studies written without it still read.
    if (entry.contains("ci_low_bonferroni")) {
      BootstrapInterval family;
      family.low = FieldAs<double>(entry, "ci_low_bonferroni", at);
      family.high = FieldAs<double>(entry, "ci_high_bonferroni", at);
      family.resamples = study.options.bootstrap.resamples;
      c.family_interval = family;
      c.survives_family = FieldAs<bool>(entry, "survives_bonferroni", at);
    }
    study.correlations.push_back(std::move(c));
  }
  return study;
}

}  // namespace slamsweep::evaluator::inline validity
