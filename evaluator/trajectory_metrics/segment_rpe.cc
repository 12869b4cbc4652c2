#include "evaluator/trajectory_metrics/segment_rpe.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline trajectory_metrics {
namespace {

nlohmann::json OptionalStatistics(const std::optional<ErrorStatistics>& statistics) {
  return statistics ? nlohmann::json(*statistics) : nlohmann::json(nullptr);
}

std::optional<ErrorStatistics> StatisticsOrNone(const std::vector<double>& errors) {
  if (errors.empty()) return std::nullopt;
  return ComputeStatistics(errors);
}

}  // namespace

double PathLengthM(const Trajectory& trajectory) {
  const std::vector<Pose>& poses = trajectory.poses();
  double length = 0.0;
  for (std::size_t i = 1; i < poses.size(); ++i) length += (poses[i].position - poses[i - 1].position).norm();
  return length;
}

std::vector<double> DefaultSegmentLengthsM(double path_length_m) {
  std::vector<double> lengths;
  if (!std::isfinite(path_length_m) || path_length_m <= 0.0) return lengths;
  for (const double fraction : {0.1, 0.2, 0.3, 0.4, 0.5}) {
    const double rounded = std::round(fraction * path_length_m);
    if (rounded >= 1.0 && (lengths.empty() || lengths.back() != rounded)) lengths.push_back(rounded);
  }
  return lengths;
}

void ValidateSegmentLengths(const std::vector<double>& lengths_m) {
  for (std::size_t i = 0; i < lengths_m.size(); ++i) {
    std::ostringstream length;
    length << lengths_m[i];
    if (!std::isfinite(lengths_m[i]) || lengths_m[i] <= 0.0) {
      throw InputError("segment lengths: expected finite lengths > 0 m, got " + length.str());
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (lengths_m[j] == lengths_m[i]) throw InputError("segment lengths: " + length.str() + " m is listed twice");
    }
  }
}

SegmentRpe::SegmentRpe(SegmentRpeOptions options) : options_(std::move(options)) {
  ValidateSegmentLengths(options_.lengths_m);
  if (options_.lengths_m.empty()) throw InputError("segment lengths: expected at least one length");
  ValidateAssociationOptions(options_.association);
  for (const double length : options_.lengths_m) {
    ValidatePairSelectionOptions({length, DeltaUnit::kMeters, true, options_.relative_tolerance});
  }
  std::sort(options_.lengths_m.begin(), options_.lengths_m.end());
}

SegmentRpeResult SegmentRpe::Compute(const Trajectory& reference, const Trajectory& estimate) const {
  const AssociatedIndices association = AssociateIndices(reference, estimate, options_.association);
  const PairedSide paired_reference(reference, association.reference_ids);
  const PairedSide paired_estimate(estimate, association.estimate_ids);
  const std::vector<Pose>& q = paired_reference.trajectory().poses();
  const std::vector<Pose>& p = paired_estimate.trajectory().poses();
  const std::vector<double>& stamps = paired_reference.trajectory().stamps_s();

  SegmentRpeResult result;
  result.specification = ToJson(options_.association);
  result.specification["lengths_m"] = options_.lengths_m;
  result.specification["delta_unit"] = "m";
  result.specification["all_pairs"] = true;
  result.specification["pairs_from"] = "reference";
  result.specification["delta_tolerance"] = options_.relative_tolerance;
  result.specification["alignment"] = "none";
  result.pairs = association.size();
  result.reference_unpaired = association.reference_unpaired;
  result.estimate_unpaired = association.estimate_unpaired;

  for (const double length : options_.lengths_m) {
    SegmentLengthResult segments;
    segments.length_m = length;
    segments.pairs =
        FindPairs(paired_reference.trajectory(), {length, DeltaUnit::kMeters, true, options_.relative_tolerance});
    for (const auto [i, j] : segments.pairs) {
      const Pose error = Relative(Relative(q[i], q[j]), Relative(p[i], p[j]));
      const double translation = error.position.norm();
      segments.start_s.push_back(stamps[i]);
      segments.end_s.push_back(stamps[j]);
      segments.translation_m.push_back(translation);
      segments.translation_pct.push_back(100.0 * translation / length);
      segments.rotation_deg_per_m.push_back(RadToDeg(RotationAngleRad(error.orientation)) / length);
    }
    segments.translation_m_statistics = StatisticsOrNone(segments.translation_m);
    segments.translation_pct_statistics = StatisticsOrNone(segments.translation_pct);
    segments.rotation_deg_per_m_statistics = StatisticsOrNone(segments.rotation_deg_per_m);
    result.lengths.push_back(std::move(segments));
  }
  return result;
}

nlohmann::json SegmentRpeResult::ToJson() const {
  nlohmann::json lengths_json = nlohmann::json::array();
  for (const SegmentLengthResult& segments : lengths) {
    lengths_json.push_back({{"length_m", segments.length_m},
                            {"n", segments.pairs.size()},
                            {"translation_m", OptionalStatistics(segments.translation_m_statistics)},
                            {"translation_pct", OptionalStatistics(segments.translation_pct_statistics)},
                            {"rotation_deg_per_m", OptionalStatistics(segments.rotation_deg_per_m_statistics)}});
  }
  return {{"specification", specification},
          {"pairs", pairs},
          {"reference_unpaired", reference_unpaired},
          {"estimate_unpaired", estimate_unpaired},
          {"lengths", std::move(lengths_json)}};
}

}  // namespace slamsweep::evaluator::inline trajectory_metrics
