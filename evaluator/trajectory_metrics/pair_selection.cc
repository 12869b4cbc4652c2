#include "evaluator/trajectory_metrics/pair_selection.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include "evaluator/core/input_error.h"
#include "evaluator/trajectory_metrics/index_search.h"

namespace slamsweep::evaluator::inline trajectory_metrics {
namespace {

std::string FormatNumber(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.9g", value);
  return buffer;
}

// numpy's deg2rad multiplies by pi/180; doing the same keeps threshold decisions identical.
double DegreesToRadians(double degrees) { return degrees * (std::numbers::pi / 180.0); }

// The distance between neighbouring poses k-1 and k, summed in the order numpy's row norm uses.
double StepDistance(const Pose& previous, const Pose& current) {
  const Eigen::Vector3d d = previous.position - current.position;
  return std::sqrt(d.x() * d.x() + d.y() * d.y() + d.z() * d.z());
}

// One "step length" between neighbouring poses: metres travelled or seconds elapsed.
template <typename Step>
std::vector<IndexPair> ConsecutiveByAccumulation(std::size_t count, double delta, Step step) {
  std::vector<std::size_t> ids;
  double accumulated = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    if (i > 0) accumulated += step(i);
    if (accumulated >= delta) {
      ids.push_back(i);
      accumulated = 0.0;
    }
  }
  std::vector<IndexPair> pairs;
  for (std::size_t k = 1; k < ids.size(); ++k) pairs.push_back({ids[k - 1], ids[k]});
  return pairs;
}

// evo's all-pairs path rule: for each i the j > i minimising |(d_j - d_i) - delta| (first j on a
// tie), kept when that is at most `tolerance`. d is non-decreasing, and so is the rounded value
// (d_j - d_i) - delta, so the minimum sits at the sign change, found by binary search; ties before
// the sign change form a run ending there, whose first element is again found by binary search.
template <typename Step>
std::vector<IndexPair> AllPairsByAccumulation(std::size_t count, double delta, double tolerance, Step step) {
  std::vector<double> accumulated(count, 0.0);
  for (std::size_t k = 1; k < count; ++k) accumulated[k] = accumulated[k - 1] + step(k);

  std::vector<IndexPair> pairs;
  for (std::size_t i = 0; i + 1 < count; ++i) {
    const double start = accumulated[i];
    const auto signed_gap = [&](std::size_t j) { return (accumulated[j] - start) - delta; };
    const std::size_t split = PartitionPointIndex(i + 1, count, [&](std::size_t j) { return signed_gap(j) < 0.0; });
    double best = std::numeric_limits<double>::infinity();
    std::size_t candidate = split;
    if (split < count) best = signed_gap(split);
    if (split > i + 1 && std::abs(signed_gap(split - 1)) <= best) {
      best = std::abs(signed_gap(split - 1));
      candidate = PartitionPointIndex(i + 1, split, [&](std::size_t j) { return std::abs(signed_gap(j)) > best; });
    }
    if (best > tolerance) continue;
    pairs.push_back({i, candidate});
  }
  return pairs;
}

double AngleBetweenRad(const Pose& a, const Pose& b) {
  return RotationAngleRad(a.orientation.conjugate() * b.orientation);
}

std::vector<IndexPair> PairsByIndex(std::size_t count, std::size_t delta, bool all_pairs) {
  std::vector<IndexPair> pairs;
  if (all_pairs) {
    for (std::size_t i = 0; i + delta < count; ++i) pairs.push_back({i, i + delta});
  } else {
    for (std::size_t i = 0; i + delta < count; i += delta) pairs.push_back({i, i + delta});
  }
  return pairs;
}

std::vector<IndexPair> PairsByAngle(const std::vector<Pose>& poses, double delta_deg, double tolerance_deg,
                                    bool all_pairs) {
  const double delta_rad = DegreesToRadians(delta_deg);
  const double tolerance_rad = DegreesToRadians(tolerance_deg);
  std::vector<IndexPair> pairs;
  if (all_pairs) {
    const double lower = delta_rad - tolerance_rad;
    const double upper = delta_rad + tolerance_rad;
    for (std::size_t i = 0; i + 1 < poses.size(); ++i) {
      const Eigen::Quaterniond inverse = poses[i].orientation.conjugate();
      for (std::size_t j = i + 1; j < poses.size(); ++j) {
        const double angle = RotationAngleRad(inverse * poses[j].orientation);
        if (lower <= angle && angle <= upper) pairs.push_back({i, j});
      }
    }
    return pairs;
  }
  double accumulated = 0.0;
  std::size_t start = 0;
  for (std::size_t end = 1; end < poses.size(); ++end) {
    accumulated += AngleBetweenRad(poses[end - 1], poses[end]);
    if (accumulated >= delta_rad) {
      pairs.push_back({start, end});
      accumulated = 0.0;
      start = end;
    }
  }
  return pairs;
}

}  // namespace

DeltaUnit ParseDeltaUnit(std::string_view name) {
  if (name == "f") return DeltaUnit::kFrames;
  if (name == "m") return DeltaUnit::kMeters;
  if (name == "s") return DeltaUnit::kSeconds;
  if (name == "d") return DeltaUnit::kDegrees;
  throw InputError("delta unit: expected one of f (frames), m (metres), s (seconds), d (degrees); got '" +
                   std::string(name) + "'");
}

std::string_view DeltaUnitName(DeltaUnit unit) {
  switch (unit) {
    case DeltaUnit::kFrames:
      return "f";
    case DeltaUnit::kMeters:
      return "m";
    case DeltaUnit::kSeconds:
      return "s";
    case DeltaUnit::kDegrees:
      return "d";
  }
  return "f";
}

void ValidatePairSelectionOptions(const PairSelectionOptions& options) {
  if (!std::isfinite(options.delta) || options.delta < 0.0) {
    throw InputError("option delta (--delta): expected a finite number >= 0, got " + FormatNumber(options.delta));
  }
  if (options.unit == DeltaUnit::kFrames && (options.delta < 1.0 || std::floor(options.delta) != options.delta)) {
    throw InputError("option delta (--delta): expected a whole number of frames >= 1 for delta unit f, got " +
                     FormatNumber(options.delta));
  }
  if (options.unit == DeltaUnit::kDegrees && options.delta > 180.0) {
    throw InputError("option delta (--delta): a rotation angle lies in [0, 180] degrees, got " +
                     FormatNumber(options.delta));
  }
  if (!std::isfinite(options.relative_tolerance) || options.relative_tolerance < 0.0) {
    throw InputError("RPE pair selection: expected a relative tolerance >= 0, got " +
                     FormatNumber(options.relative_tolerance));
  }
}

std::vector<IndexPair> FindPairs(const Trajectory& trajectory, const PairSelectionOptions& options) {
  ValidatePairSelectionOptions(options);
  const std::vector<Pose>& poses = trajectory.poses();
  const std::vector<double>& stamps = trajectory.stamps_s();
  const std::size_t count = poses.size();
  const double tolerance = options.delta * options.relative_tolerance;
  const auto step_distance = [&](std::size_t k) { return StepDistance(poses[k - 1], poses[k]); };
  const auto step_time = [&](std::size_t k) { return std::abs(stamps[k] - stamps[k - 1]); };

  std::vector<IndexPair> pairs;
  switch (options.unit) {
    case DeltaUnit::kFrames:
      // Clamped before the cast: a huge delta must give "no pairs", not an out-of-range conversion.
      pairs = PairsByIndex(
          count, options.delta >= static_cast<double>(count) ? count : static_cast<std::size_t>(options.delta),
          options.all_pairs);
      break;
    case DeltaUnit::kMeters:
      pairs = options.all_pairs ? AllPairsByAccumulation(count, options.delta, tolerance, step_distance)
                                : ConsecutiveByAccumulation(count, options.delta, step_distance);
      break;
    case DeltaUnit::kSeconds:
      pairs = options.all_pairs ? AllPairsByAccumulation(count, options.delta, tolerance, step_time)
                                : ConsecutiveByAccumulation(count, options.delta, step_time);
      break;
    case DeltaUnit::kDegrees:
      pairs = PairsByAngle(poses, options.delta, tolerance, options.all_pairs);
      break;
  }
  return pairs;
}

std::vector<IndexPair> SelectPairs(const Trajectory& trajectory, const PairSelectionOptions& options) {
  std::vector<IndexPair> pairs = FindPairs(trajectory, options);
  if (pairs.empty()) {
    const std::size_t count = trajectory.size();
    throw InputError("RPE: delta = " + FormatNumber(options.delta) + " (" + std::string(DeltaUnitName(options.unit)) +
                     (options.all_pairs ? ", all pairs" : ", consecutive pairs") + ") selects no pose pairs among " +
                     std::to_string(count) + " associated poses; try a smaller --delta or another --delta-unit");
  }
  return pairs;
}

}  // namespace slamsweep::evaluator::inline trajectory_metrics
