#include "evaluator/sequence/record_order_check.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace slamsweep::evaluator::inline sequence {
namespace {

/// Mean absolute range difference over the beams that hit in both scans; 0 when none does.
double ScanChange(const LaserScan& a, const LaserScan& b) {
  double sum = 0.0;
  std::size_t beams = 0;
  for (std::size_t i = 0; i < a.ranges_m.size() && i < b.ranges_m.size(); ++i) {
    if (!a.IsHit(a.ranges_m[i]) || !b.IsHit(b.ranges_m[i])) continue;
    sum += std::abs(static_cast<double>(a.ranges_m[i]) - static_cast<double>(b.ranges_m[i]));
    ++beams;
  }
  return beams == 0 ? 0.0 : sum / static_cast<double>(beams);
}

double Travel(const Pose& a, const Pose& b) { return (b.position - a.position).head<2>().norm(); }

}  // namespace

RecordOrderCheck CheckRecordOrder(std::span<const LaserScan> scans, std::span<const Pose> odometry,
                                  std::span<const double> recorded_stamps_s) {
  RecordOrderCheck check;
  const std::size_t n = std::min({scans.size(), odometry.size(), recorded_stamps_s.size()});
  // Records i - 1 and i swap places under stamp order; i - 2 and i + 1 are their neighbours either way.
  for (std::size_t i = 2; i + 1 < n; ++i) {
    if (recorded_stamps_s[i] >= recorded_stamps_s[i - 1]) continue;
    ++check.steps;
    const auto in_file_order = [&](auto change) { return change(i - 2, i - 1) + change(i - 1, i) + change(i, i + 1); };
    const auto in_stamp_order = [&](auto change) { return change(i - 2, i) + change(i, i - 1) + change(i - 1, i + 1); };
    const auto scan_change = [&](std::size_t a, std::size_t b) { return ScanChange(scans[a], scans[b]); };
    const auto travel = [&](std::size_t a, std::size_t b) { return Travel(odometry[a], odometry[b]); };
    const double scans_file = in_file_order(scan_change);
    const double scans_stamp = in_stamp_order(scan_change);
    if (scans_file < scans_stamp) ++check.scans_closer_in_file_order;
    if (scans_stamp < scans_file) ++check.scans_closer_in_stamp_order;
    const double travel_file = in_file_order(travel);
    const double travel_stamp = in_stamp_order(travel);
    if (travel_file < travel_stamp) ++check.odometry_shorter_in_file_order;
    if (travel_stamp < travel_file) ++check.odometry_shorter_in_stamp_order;
  }
  return check;
}

nlohmann::json RecordOrderCheckJson(const RecordOrderCheck& check) {
  return {{"steps", check.steps},
          {"scans_closer_in_file_order", check.scans_closer_in_file_order},
          {"scans_closer_in_stamp_order", check.scans_closer_in_stamp_order},
          {"odometry_shorter_in_file_order", check.odometry_shorter_in_file_order},
          {"odometry_shorter_in_stamp_order", check.odometry_shorter_in_stamp_order}};
}

}  // namespace slamsweep::evaluator::inline sequence
