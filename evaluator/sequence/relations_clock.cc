#include "evaluator/sequence/relations_clock.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_map>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/core/pose.h"
#include "evaluator/sequence/scan_overlay.h"
#include "evaluator/trajectory_metrics/interpolation.h"

namespace slamsweep::evaluator::inline sequence {
namespace {

/// The reading stamp nearest `stamp` in the sorted `readings`.
double Nearest(const std::vector<double>& readings, double stamp) {
  const auto at = std::lower_bound(readings.begin(), readings.end(), stamp);
  if (at == readings.end()) return readings.back();
  if (at == readings.begin()) return *at;
  return (*at - stamp) < (stamp - *std::prev(at)) ? *at : *std::prev(at);
}

struct Line {
  double offset_s = 0.0;
  double rate = 1.0;
};

/// Least squares reading = offset + rate * relation over the relation stamps whose nearest reading
/// under `line` lies within `tolerance_s`; the relation stamps are centred first, as they can be
/// around 1e9 s.
Line Refit(const std::vector<double>& relations, const std::vector<double>& readings, const Line& line,
           double tolerance_s, std::size_t& matched) {
  std::vector<std::pair<double, double>> pairs;
  for (double relation : relations) {
    const double mapped = line.offset_s + line.rate * relation;
    const double reading = Nearest(readings, mapped);
    if (std::abs(reading - mapped) <= tolerance_s) pairs.emplace_back(relation, reading);
  }
  matched = pairs.size();
  if (pairs.size() < 2) {
    throw InputError(fmt::format("relations clock: only {} of {} relation stamps lie within {} s of a reading",
                                 pairs.size(), relations.size(), tolerance_s));
  }
  double mean_x = 0.0;
  double mean_y = 0.0;
  for (const auto& [x, y] : pairs) {
    mean_x += x;
    mean_y += y;
  }
  mean_x /= static_cast<double>(pairs.size());
  mean_y /= static_cast<double>(pairs.size());
  double sxx = 0.0;
  double sxy = 0.0;
  for (const auto& [x, y] : pairs) {
    sxx += (x - mean_x) * (x - mean_x);
    sxy += (x - mean_x) * (y - mean_y);
  }
  const double rate = sxx > 0.0 ? sxy / sxx : 1.0;
  return Line{mean_y - rate * mean_x, rate};
}

}  // namespace

nlohmann::json RelationsClockFit::ToJson() const {
  return nlohmann::json{{"offset_s", offset_s},
                        {"rate", rate},
                        {"stamps", stamps},
                        {"matched", matched},
                        {"matched_within_10ms", matched_within_10ms},
                        {"tolerance_s", tolerance_s},
                        {"rms_residual_s", rms_residual_s},
                        {"max_abs_residual_s", max_abs_residual_s},
                        {"drift_over_span_s", drift_over_span_s}};
}

RelationsClockFit FitRelationsClock(std::span<const double> relation_stamps_s, std::span<const double> reading_stamps_s,
                                    const RelationsClockFitOptions& options) {
  std::vector<double> relations(relation_stamps_s.begin(), relation_stamps_s.end());
  std::sort(relations.begin(), relations.end());
  relations.erase(std::unique(relations.begin(), relations.end()), relations.end());
  std::vector<double> readings(reading_stamps_s.begin(), reading_stamps_s.end());
  std::sort(readings.begin(), readings.end());
  if (relations.empty() || readings.empty()) throw InputError("relations clock: no relation stamps or no readings");

  // Coarse offset: the most frequent difference between any reading and any relation stamp.
  std::unordered_map<long long, std::size_t> histogram;
  for (double relation : relations) {
    if (options.start_offset_s) break;
    for (double reading : readings) ++histogram[std::llround((reading - relation) / options.coarse_bin_s)];
  }
  long long best_bin = 0;
  std::size_t best_count = 0;
  for (const auto& [bin, count] : histogram) {
    // Two neighbouring bins together: a drifting offset spreads over a bin border.
    const auto next = histogram.find(bin + 1);
    const std::size_t pair_count = count + (next == histogram.end() ? 0 : next->second);
    if (pair_count > best_count || (pair_count == best_count && bin < best_bin)) {
      best_bin = bin;
      best_count = pair_count;
    }
  }
  std::vector<double> spacing;
  for (std::size_t i = 1; i < readings.size(); ++i) spacing.push_back(readings[i] - readings[i - 1]);
  double tolerance_s = options.coarse_bin_s;
  if (!spacing.empty()) {
    std::nth_element(spacing.begin(), spacing.begin() + static_cast<std::ptrdiff_t>(spacing.size() / 2), spacing.end());
    tolerance_s = std::max(tolerance_s, 0.5 * spacing[spacing.size() / 2]);
  }
  Line line{(static_cast<double>(best_bin) + 0.5) * options.coarse_bin_s, 1.0};
  if (options.start_offset_s) line = Line{*options.start_offset_s, options.start_rate};
  std::size_t matched = 0;
  for (int round = 0; round < 3; ++round) line = Refit(relations, readings, line, tolerance_s, matched);

  RelationsClockFit fit;
  fit.offset_s = line.offset_s;
  fit.rate = line.rate;
  fit.stamps = relations.size();
  fit.matched = matched;
  fit.tolerance_s = tolerance_s;
  constexpr double kExactS = 0.01;
  double sum_squares = 0.0;
  for (double relation : relations) {
    const double mapped = line.offset_s + line.rate * relation;
    const double residual = Nearest(readings, mapped) - mapped;
    if (std::abs(residual) <= kExactS) ++fit.matched_within_10ms;
    if (std::abs(residual) > tolerance_s) continue;
    sum_squares += residual * residual;
    fit.max_abs_residual_s = std::max(fit.max_abs_residual_s, std::abs(residual));
  }
  fit.rms_residual_s = std::sqrt(sum_squares / static_cast<double>(matched));
  fit.drift_over_span_s = (line.rate - 1.0) * (relations.back() - relations.front());
  return fit;
}

namespace {

/// The odometry's yaw at `stamp_s`, interpolated between readings (their yaw unwrapped), or nullopt
/// outside them.
class UnwrappedYaw {
 public:
  explicit UnwrappedYaw(const Trajectory& readings) : stamps_(readings.stamps_s()) {
    yaw_.reserve(readings.size());
    for (const Pose& pose : readings.poses()) {
      const double yaw = pose.Yaw();
      yaw_.push_back(yaw_.empty() ? yaw : yaw_.back() + NormalizeAngleRad(yaw - yaw_.back()));
    }
  }
  std::optional<double> At(double stamp_s) const {
    const auto after = std::upper_bound(stamps_.begin(), stamps_.end(), stamp_s);
    if (after == stamps_.begin() || after == stamps_.end()) return std::nullopt;
    const std::size_t below = static_cast<std::size_t>(after - stamps_.begin()) - 1;
    const double fraction = (stamp_s - stamps_[below]) / (stamps_[below + 1] - stamps_[below]);
    return yaw_[below] + fraction * (yaw_[below + 1] - yaw_[below]);
  }

 private:
  const std::vector<double>& stamps_;
  std::vector<double> yaw_;
};

/// Mean absolute difference (deg) between each relation's rotation and the odometry's over its
/// interval shifted by `offset_s`; infinity when a relation falls outside the readings.
double RotationDisagreementDeg(const std::vector<const Relation*>& relations, const UnwrappedYaw& yaw,
                               double offset_s) {
  double sum = 0.0;
  for (const Relation* relation : relations) {
    const std::optional<double> from = yaw.At(relation->t1_s + offset_s);
    const std::optional<double> to = yaw.At(relation->t2_s + offset_s);
    if (!from || !to) return std::numeric_limits<double>::infinity();
    sum += std::abs(NormalizeAngleRad((*to - *from) - relation->delta.Yaw()));
  }
  return RadToDeg(sum / static_cast<double>(relations.size()));
}

struct OffsetSearch {
  double offset_s = 0.0;
  double best = 0.0;
  double next_best = 0.0;
};

/// The offset in [low, high] where `disagreement` is lowest: every 10 ms, then every 1 ms around it;
/// next_best is the lowest found more than 0.1 s away (the margin by which the fit is unambiguous).
OffsetSearch SearchOffset(const std::function<double(double)>& disagreement, double low_s, double high_s) {
  std::vector<std::pair<double, double>> coarse;
  for (double offset = low_s; offset <= high_s; offset += 0.01) coarse.emplace_back(offset, disagreement(offset));
  const auto best =
      std::min_element(coarse.begin(), coarse.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  OffsetSearch search{best->first, best->second, std::numeric_limits<double>::infinity()};
  for (const auto& [offset, value] : coarse) {
    if (std::abs(offset - best->first) > 0.1) search.next_best = std::min(search.next_best, value);
  }
  const double centre = best->first;
  for (double offset = centre - 0.01; offset <= centre + 0.01; offset += 0.001) {
    const double value = disagreement(offset);
    if (value < search.best) search = {offset, value, search.next_best};
  }
  return search;
}

/// How badly a set of relations agrees with the log under a clock offset (lower is better).
using Disagreement = std::function<double(const std::vector<const Relation*>&, double)>;

struct HalvesFit {
  OffsetSearch whole;
  double early_offset_s = 0.0;
  double late_offset_s = 0.0;
  /// t_log = rate * t + offset, the line through the two halves' offsets at their middle stamps.
  double offset_s = 0.0;
  double rate = 1.0;

  /// The fit over `relations` relations, its disagreements shown in `unit` by `shown`.
  SearchedClockFit Fit(std::size_t relations, const char* unit, const std::function<double(double)>& shown) const {
    SearchedClockFit fit;
    fit.offset_s = offset_s;
    fit.rate = rate;
    fit.relations = relations;
    fit.disagreement = shown(whole.best);
    fit.next_best_disagreement = shown(whole.next_best);
    fit.unit = unit;
    fit.first_half_offset_s = early_offset_s;
    fit.second_half_offset_s = late_offset_s;
    return fit;
  }
};

/// The offset in [low, high] where `disagreement` over all of `sorted` (by t1) is lowest; then each
/// half's offset within `half_window_s` of it, and the line through the two for the rate.
HalvesFit FitOverHalves(const std::vector<const Relation*>& sorted, const Disagreement& disagreement, double low_s,
                        double high_s, double half_window_s) {
  const auto over = [&disagreement](const std::vector<const Relation*>& subset) {
    return [&disagreement, &subset](double offset_s) { return disagreement(subset, offset_s); };
  };
  HalvesFit fit;
  fit.whole = SearchOffset(over(sorted), low_s, high_s);
  const auto half = static_cast<std::ptrdiff_t>(sorted.size() / 2);
  const std::vector<const Relation*> first(sorted.begin(), sorted.begin() + half);
  const std::vector<const Relation*> second(sorted.begin() + half, sorted.end());
  const double low = fit.whole.offset_s - half_window_s;
  const double high = fit.whole.offset_s + half_window_s;
  fit.early_offset_s = SearchOffset(over(first), low, high).offset_s;
  fit.late_offset_s = SearchOffset(over(second), low, high).offset_s;
  const double early_t = first[first.size() / 2]->t1_s;
  const double late_t = second[second.size() / 2]->t1_s;
  const double slope = (fit.late_offset_s - fit.early_offset_s) / (late_t - early_t);
  fit.offset_s = fit.early_offset_s - slope * early_t;
  fit.rate = 1.0 + slope;
  return fit;
}

}  // namespace

nlohmann::json SearchedClockFit::ToJson() const {
  return nlohmann::json{{"offset_s", offset_s},
                        {"rate", rate},
                        {"relations", relations},
                        {"disagreement", disagreement},
                        {"next_best_disagreement", next_best_disagreement},
                        {"unit", unit},
                        {"first_half_offset_s", first_half_offset_s},
                        {"second_half_offset_s", second_half_offset_s}};
}

SearchedClockFit FitRelationsClockByOdometry(const Relations& relations, const Trajectory& readings) {
  if (readings.size() < 2 || relations.empty()) throw InputError("relations clock: too few readings or relations");
  std::vector<double> spans;
  for (const Relation& relation : relations) spans.push_back(std::abs(relation.t2_s - relation.t1_s));
  std::nth_element(spans.begin(), spans.begin() + static_cast<std::ptrdiff_t>(spans.size() / 2), spans.end());
  const double median_span_s = spans[spans.size() / 2];
  std::vector<const Relation*> chosen;
  double first_stamp = std::numeric_limits<double>::infinity();
  double last_stamp = -std::numeric_limits<double>::infinity();
  for (const Relation& relation : relations) {
    first_stamp = std::min({first_stamp, relation.t1_s, relation.t2_s});
    last_stamp = std::max({last_stamp, relation.t1_s, relation.t2_s});
    if (std::abs(relation.t2_s - relation.t1_s) <= median_span_s) chosen.push_back(&relation);
  }
  std::sort(chosen.begin(), chosen.end(), [](const Relation* a, const Relation* b) { return a->t1_s < b->t1_s; });
  if (chosen.size() < 4) throw InputError("relations clock: fewer than 4 short relations");
  const double low_s = readings.StartS() - first_stamp;
  const double high_s = readings.EndS() - last_stamp;
  if (low_s > high_s) {
    throw InputError("relations clock: the relations span more time than the readings; no offset puts them inside");
  }
  const UnwrappedYaw yaw(readings);
  const Disagreement disagreement = [&yaw](const std::vector<const Relation*>& subset, double offset_s) {
    return RotationDisagreementDeg(subset, yaw, offset_s);
  };
  // Each half within 0.5 s of the whole fit (the drift over a run is far below a second).
  const HalvesFit halves = FitOverHalves(chosen, disagreement, low_s, high_s, 0.5);

  return halves.Fit(chosen.size(), "deg", [](double mean_abs_deg) { return mean_abs_deg; });
}

namespace {

/// A placed hit farther than this from every hit of the other scan counts as this far.
constexpr double kOverlayRadiusM = 0.10;
/// Scans with fewer hits than this are not laid over each other.
constexpr std::size_t kMinOverlayHits = 20;

/// Each scan's hits and nearest-hit look-ups, and the mean overlay residual of a set of relations
/// under a clock offset.
class ScanOverlays {
 public:
  ScanOverlays(std::span<const LaserScan> scans, const Trajectory& odometry) : odometry_(odometry) {
    stamps_.reserve(scans.size());
    hits_.reserve(scans.size());
    neighbours_.reserve(scans.size());
    for (const LaserScan& scan : scans) {
      stamps_.push_back(scan.stamp_s);
      hits_.push_back(HitsOnRobot(scan));
      neighbours_.emplace_back(scan, kOverlayRadiusM);
    }
  }

  /// Mean squared distance (m^2, capped) of the scan nearest each relation's mapped t2, placed over
  /// the scan nearest its mapped t1 by the relation, with the odometry's motion between each scan and
  /// the mapped stamp beside it (a fraction of a scan period, so a lag of the odometry hardly enters);
  /// relations outside the scans, or whose two stamps name one scan, are left out. Infinity when none
  /// is left.
  double MeanResidual(const std::vector<const Relation*>& relations, double offset_s) const {
    double sum = 0.0;
    std::size_t used = 0;
    for (const Relation* relation : relations) {
      const std::optional<std::size_t> from = NearestScan(relation->t1_s + offset_s);
      const std::optional<std::size_t> to = NearestScan(relation->t2_s + offset_s);
      if (!from || !to || *from == *to) continue;
      const std::vector<Eigen::Vector3d>& hits = hits_[*to];
      if (hits.size() < kMinOverlayHits || neighbours_[*from].HitCount() < kMinOverlayHits) continue;
      const std::optional<Pose> from_scan = odometry_.At(stamps_[*from]);
      const std::optional<Pose> from_relation = odometry_.At(relation->t1_s + offset_s);
      const std::optional<Pose> to_relation = odometry_.At(relation->t2_s + offset_s);
      const std::optional<Pose> to_scan = odometry_.At(stamps_[*to]);
      if (!from_scan || !from_relation || !to_relation || !to_scan) continue;
      const Pose placement = Relative(*from_scan, *from_relation) * relation->delta * Relative(*to_relation, *to_scan);
      sum += OverlayResidual(neighbours_[*from], hits, placement.ToIsometry()) / static_cast<double>(hits.size());
      ++used;
    }
    return used == 0 ? std::numeric_limits<double>::infinity() : sum / static_cast<double>(used);
  }

 private:
  std::optional<std::size_t> NearestScan(double stamp_s) const {
    if (stamp_s < stamps_.front() || stamp_s > stamps_.back()) return std::nullopt;
    const auto at = std::lower_bound(stamps_.begin(), stamps_.end(), stamp_s);
    const auto index = static_cast<std::size_t>(at - stamps_.begin());
    if (index == 0) return index;
    return (stamps_[index] - stamp_s) < (stamp_s - stamps_[index - 1]) ? index : index - 1;
  }

  TrajectoryInterpolator odometry_;
  std::vector<double> stamps_;
  std::vector<std::vector<Eigen::Vector3d>> hits_;
  std::vector<ScanNeighbours> neighbours_;
};

}  // namespace

SearchedClockFit FitRelationsClockByScans(const Relations& relations, std::span<const LaserScan> scans,
                                          const Trajectory& odometry, double start_offset_s, double search_s) {
  if (scans.size() < 2 || relations.size() < 4) throw InputError("relations clock: too few scans or relations");
  for (std::size_t i = 1; i < scans.size(); ++i) {
    if (!(scans[i].stamp_s > scans[i - 1].stamp_s)) throw InputError("relations clock: scan stamps must increase");
  }
  std::vector<const Relation*> all;
  for (const Relation& relation : relations) all.push_back(&relation);
  std::sort(all.begin(), all.end(), [](const Relation* a, const Relation* b) { return a->t1_s < b->t1_s; });
  const ScanOverlays overlays(scans, odometry);
  const Disagreement residual = [&overlays](const std::vector<const Relation*>& subset, double offset_s) {
    return overlays.MeanResidual(subset, offset_s);
  };
  const HalvesFit halves = FitOverHalves(all, residual, start_offset_s - search_s, start_offset_s + search_s, search_s);
  if (!std::isfinite(halves.whole.best)) {
    throw InputError("relations clock: no offset near the start lays a relation on the scans");
  }

  return halves.Fit(all.size(), "cm rms", [](double mean_square_m2) { return 100.0 * std::sqrt(mean_square_m2); });
}

}  // namespace slamsweep::evaluator::inline sequence
