#include "evaluator/sequence/scan_spacing.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline sequence {

namespace {

/// The value at rank (n - 1) * p of the sorted values, interpolated between its neighbours.
double Percentile(const std::vector<double>& sorted, double p) {
  const double rank = static_cast<double>(sorted.size() - 1) * p;
  const auto below = static_cast<std::size_t>(std::floor(rank));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double fraction = rank - static_cast<double>(below);
  return sorted[below] + fraction * (sorted[above] - sorted[below]);
}

SpacingPercentiles PercentilesOf(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return {Percentile(values, 0.5), Percentile(values, 0.95)};
}

nlohmann::json PercentilesJson(const SpacingPercentiles& percentiles) {
  return {{"median", percentiles.median}, {"p95", percentiles.p95}};
}

SpacingPercentiles PercentilesFromJson(const nlohmann::json& block, const char* field) {
  const auto found = block.find(field);
  const std::string name = std::string("scan_spacing.") + field;
  if (found == block.end() || !found->is_object()) throw InputError(name + ": expected {median, p95}");
  SpacingPercentiles percentiles;
  for (const auto& [key, target] : {std::pair{"median", &percentiles.median}, std::pair{"p95", &percentiles.p95}}) {
    const auto value = found->find(key);
    if (value == found->end() || !value->is_number()) throw InputError(name + "." + key + ": expected a number");
    *target = value->get<double>();
  }
  return percentiles;
}

}  // namespace

std::optional<ScanSpacing> ComputeScanSpacing(const Sequence& sequence) {
  const std::size_t scans = sequence.scans.size();
  if (scans < 2 || sequence.odometry.size() != scans) return std::nullopt;
  std::vector<double> gaps, travels, rotations;
  gaps.reserve(scans - 1);
  travels.reserve(scans - 1);
  rotations.reserve(scans - 1);
  const std::vector<Pose>& poses = sequence.odometry.poses();
  ScanSpacing spacing;
  spacing.steps = scans - 1;
  for (std::size_t i = 1; i < scans; ++i) {
    gaps.push_back(sequence.scans[i].stamp_s - sequence.scans[i - 1].stamp_s);
    travels.push_back((poses[i].position - poses[i - 1].position).norm());
    rotations.push_back(RotationAngleRad(poses[i - 1].orientation.conjugate() * poses[i].orientation));
    if (travels.back() > 0.0 || rotations.back() > 0.0) spacing.odometry_moves = true;
  }
  spacing.gap_s = PercentilesOf(std::move(gaps));
  spacing.travel_m = PercentilesOf(std::move(travels));
  spacing.rotation_rad = PercentilesOf(std::move(rotations));
  return spacing;
}

SparseScanThreshold SparseScanThresholdInUse() {
  // The intel run's density study (docs/full-rate-intel.md), on one span and the same relations: every scan,
  // 0.056 m apart at the median, where Cartographer scored 0.025 m; every 5th scan, 0.284 m apart, where it
  // scored 0.18 m and vinySLAM lost to the wheels. The bound is their geometric mean (0.126 m), rounded down.
  return {0.12};
}

std::optional<bool> TooSparseForScanMatching(const ScanSpacing& spacing) {
  if (!spacing.odometry_moves) return std::nullopt;
  return spacing.travel_m.median > SparseScanThresholdInUse().median_travel_m;
}

std::string SparseScanWarning(const ScanSpacing& spacing) {
  if (TooSparseForScanMatching(spacing) != true) return {};
  return fmt::format(
      "scans too far apart for scan matching: consecutive scans are {:.2f} m apart at the median (by the "
      "odometry), beyond {:.2f} m; on the intel run Cartographer lost most of its accuracy at 0.28 m "
      "(docs/data-density.md); prefer a denser log",
      spacing.travel_m.median, SparseScanThresholdInUse().median_travel_m);
}

nlohmann::json ScanSpacingJson(const ScanSpacing& spacing) {
  const SparseScanThreshold threshold = SparseScanThresholdInUse();
  const std::optional<bool> sparse = TooSparseForScanMatching(spacing);
  return {{"steps", spacing.steps},
          {"gap_s", PercentilesJson(spacing.gap_s)},
          {"travel_m", PercentilesJson(spacing.travel_m)},
          {"rotation_rad", PercentilesJson(spacing.rotation_rad)},
          {"motion_from", "odometry poses at the scans"},
          {"odometry_moves", spacing.odometry_moves},
          {"too_sparse_for_scan_matching", sparse ? nlohmann::json(*sparse) : nlohmann::json()},
          {"threshold", {{"median_travel_m", threshold.median_travel_m}}}};
}

ScanSpacing ScanSpacingFromJson(const nlohmann::json& block) {
  if (!block.is_object()) throw InputError("scan_spacing: expected an object");
  ScanSpacing spacing;
  const auto steps = block.find("steps");
  if (steps == block.end() || !steps->is_number_unsigned()) {
    throw InputError("scan_spacing.steps: expected a count");
  }
  spacing.steps = steps->get<std::size_t>();
  spacing.gap_s = PercentilesFromJson(block, "gap_s");
  spacing.travel_m = PercentilesFromJson(block, "travel_m");
  spacing.rotation_rad = PercentilesFromJson(block, "rotation_rad");
  const auto moves = block.find("odometry_moves");
  if (moves == block.end() || !moves->is_boolean())
    throw InputError("scan_spacing.odometry_moves: expected true or false");
  spacing.odometry_moves = moves->get<bool>();
  return spacing;
}

}  // namespace slamsweep::evaluator::inline sequence
