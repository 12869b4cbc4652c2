#include "orchestrator/run/run_spec.h"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

#include "evaluator/catalog/catalog.h"
#include "evaluator/sequence/odometry_mode.h"
#include "orchestrator/run/stable_hash.h"

namespace slamsweep::orchestrator::inline run {

using nlohmann::json;

bool ThresholdApplies(const Threshold& threshold, const evaluator::CatalogEntry& entry) {
  const bool has_trajectory = evaluator::GroundTruthHasPoses(entry.ground_truth);
  const std::string& metric = threshold.metric;
  if (metric.starts_with("ape_") || metric.starts_with("rpe_") || metric.starts_with("segment_")) return has_trajectory;
  if (metric.starts_with("relations_")) return !entry.relations_path.empty();
  if (metric.starts_with("map_")) return has_trajectory || !entry.reference_map_path.empty();
  return true;
}

std::string_view SeedingName(Seeding seeding) {
  switch (seeding) {
    case Seeding::kSeeded:
      return "seeded";
    case Seeding::kDeterministic:
      return "deterministic";
    case Seeding::kUnseeded:
      return "unseeded";
  }
  return "unseeded";
}

std::string ParametersText(const json& parameters) {
  std::string text;
  if (!parameters.is_object()) return text;
  for (const auto& [name, value] : parameters.items()) {
    if (!text.empty()) text += ';';
    text += name + "=" + (value.is_string() ? value.get<std::string>() : value.dump());
  }
  return text;
}

std::string AlgorithmLabel(const std::string& algorithm, const std::string& parameters_text) {
  return parameters_text.empty() ? algorithm : fmt::format("{} [{}]", algorithm, parameters_text);
}

ComparisonGroup ComparisonGroupOf(const RunSpec& spec) {
  return ComparisonGroup{spec.sequence.entry.name, spec.algorithm.name, ParametersText(spec.algorithm.parameters),
                         spec.noise.name, OdometryModeOf(spec.sequence)};
}

std::string OdometryModeOf(const SequenceSpec& sequence) {
  return std::string(evaluator::OdometryModeName(evaluator::EffectiveOdometryMode(sequence.entry)));
}

std::string BuildSignature(const BuildIdentity& build) {
  std::vector<std::string> digests;
  for (const auto& [path, digest] : build.program_files) digests.push_back(digest);
  std::sort(digests.begin(), digests.end());
  std::string text = build.slamsweep_revision;
  for (const std::string& digest : digests) text += "\n" + digest;
  return fmt::format("b{:012x}", Fnv1a64(text) >> 16);
}

bool PlannedOdometryIsReference(const evaluator::CatalogEntry& entry, const NoiseSpec& noise) {
  return evaluator::OdometryModeApplies(entry) &&
         evaluator::EffectiveOdometryMode(entry) == evaluator::OdometryMode::kReference &&
         (!noise.odometry || *noise.odometry == evaluator::OdometryNoise{});
}

}  // namespace slamsweep::orchestrator::inline run
