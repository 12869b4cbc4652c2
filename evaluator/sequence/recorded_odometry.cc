#include "evaluator/sequence/recorded_odometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <numeric>

#include "evaluator/core/input_error.h"
#include "evaluator/sequence/relation_stamps.h"

namespace slamsweep::evaluator::inline sequence {
namespace {

constexpr double kSamePoseM = 1e-6;
constexpr double kSamePoseRad = 1e-6;
/// Half of the stamps may be lifted (see ReadingStampOptions).
constexpr double kReadingsMaxRepairedFraction = 0.5;

bool SamePose(const Pose& a, const Pose& b) {
  return (a.position - b.position).norm() <= kSamePoseM &&
         RotationAngleRad(a.orientation.inverse() * b.orientation) <= kSamePoseRad;
}

/// One record of the merged stream: a laser record (an index into `scans`) or an ODOM record.
struct Entry {
  std::size_t line = 0;
  bool laser = false;
  std::size_t index = 0;
};

std::vector<Entry> MergedByLine(const CarmenLog& log, std::span<const CarmenLaserRecord* const> scans) {
  std::vector<Entry> entries;
  entries.reserve(scans.size() + log.odometry.size());
  for (std::size_t i = 0; i < scans.size(); ++i) entries.push_back({scans[i]->line, true, i});
  for (std::size_t i = 0; i < log.odometry.size(); ++i) entries.push_back({log.odometry[i].line, false, i});
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.line < b.line; });
  return entries;
}

}  // namespace

StampOptions ReadingStampOptions(const StampOptions& scan_options) {
  StampOptions options = scan_options;
  options.max_repaired_fraction = std::max(options.max_repaired_fraction, kReadingsMaxRepairedFraction);
  return options;
}

RecordedOdometry RebuildRecordedOdometry(const CarmenLog& log, std::span<const CarmenLaserRecord* const> scans,
                                         const std::filesystem::path& source, const StampOptions& stamps) {
  RecordedOdometry out;
  std::vector<Pose> poses;
  // The chain: the corrected pose of the last keyframe and the odometry there. Before the first
  // keyframe the readings are the logged poses (anchored at the identity).
  Pose corrected_anchor;
  Pose odometry_anchor;
  const CarmenLaserRecord* previous_scan = nullptr;
  bool after_scan = false;
  std::size_t readings_since_scan = 0;
  for (const Entry& entry : MergedByLine(log, scans)) {
    if (entry.laser) {
      const CarmenLaserRecord& scan = *scans[entry.index];
      if (readings_since_scan == 0) {
        throw InputError(Located(
            source, scan.line,
            previous_scan != nullptr
                ? fmt::format("{} without a recorded ODOM reading since the {} on line {}: the log has no odometry "
                              "stream (use odometry: reference)",
                              scan.type, previous_scan->type, previous_scan->line)
                : fmt::format("{} without a recorded ODOM reading before it: the log has no odometry stream (use "
                              "odometry: reference)",
                              scan.type)));
      }
      out.scan_readings.push_back(poses.size() - 1);
      corrected_anchor = scan.robot_pose;
      odometry_anchor = poses.back();
      previous_scan = &scan;
      after_scan = true;
      readings_since_scan = 0;
      continue;
    }
    const CarmenOdomRecord& odom = log.odometry[entry.index];
    if (after_scan) {
      after_scan = false;
      if (!SamePose(odom.pose, previous_scan->robot_pose)) {
        throw InputError(
            Located(source, odom.line,
                    fmt::format("the ODOM after the {} on line {} does not repeat its pose, as a corrected "
                                "log's reset does: the log has no odometry stream to rebuild (use "
                                "odometry: reference)",
                                previous_scan->type, previous_scan->line)));
      }
      ++out.resets;
      continue;
    }
    poses.push_back(odometry_anchor * Relative(corrected_anchor, odom.pose));
    out.logged_stamps_s.push_back(odom.ipc_stamp_s);
    out.lines.push_back(odom.line);
    ++readings_since_scan;
  }
  if (scans.empty()) throw InputError(Located(source, 0, "no laser records: no odometry to rebuild for them"));

  ScanStamps chosen = ChooseScanStamps(out.logged_stamps_s, ReadingStampOptions(stamps));
  out.stamp_outcome = chosen.outcome;
  if (chosen.outcome == StampOutcome::kRecorded && !chosen.non_increasing.empty()) {
    // Policy "recorded": the stamps must increase as they are.
    const std::size_t first = chosen.non_increasing.front();
    throw InputError(Located(source, out.lines[first],
                             fmt::format("ODOM stamp {} does not come after the previous reading's {} (stamp policy "
                                         "'recorded'; 'auto' repairs such stamps)",
                                         out.logged_stamps_s[first], out.logged_stamps_s[first - 1])));
  }
  if (chosen.outcome == StampOutcome::kRepaired) {
    out.repaired_stamps = chosen.non_increasing.size();
    std::size_t repeated = 0;
    std::size_t stepped_back = 0;
    double largest_step_back_s = 0.0;
    for (std::size_t index : chosen.non_increasing) {
      const double step = out.logged_stamps_s[index] - out.logged_stamps_s[index - 1];
      if (step == 0.0) ++repeated;
      if (step < 0.0) ++stepped_back;
      largest_step_back_s = std::max(largest_step_back_s, -step);
    }
    out.warnings.push_back(Located(
        source, 0,
        fmt::format("recorded odometry: {} of {} ODOM reading stamps were lifted to the previous stamp + {} s to keep "
                    "their order strict: {} repeat the previous logged stamp, {} step back from it (by up to {:.3g} s) "
                    "and {} come before an earlier lifted one",
                    out.repaired_stamps, poses.size(), stamps.repair_step_s, repeated, stepped_back,
                    largest_step_back_s, out.repaired_stamps - repeated - stepped_back)));
  } else if (chosen.outcome == StampOutcome::kRecordOrder && stamps.policy == StampPolicy::kAuto) {
    out.warnings.push_back(Located(
        source, 0,
        fmt::format("recorded odometry: the ODOM reading stamps are unusable ({} of {} do not come after the previous "
                    "one); readings and scans are stamped in record order every {} s instead",
                    chosen.non_increasing.size(), poses.size(), stamps.record_order_period_s)));
  }
  out.readings = Trajectory(std::move(chosen.stamps_s), std::move(poses));
  return out;
}

Relations MapRelationsOntoReadings(Relations relations, const RecordedOdometry& odometry, double tolerance_s,
                                   std::size_t& unmatched) {
  return MapRelationsOntoRecords(std::move(relations), odometry.logged_stamps_s, odometry.readings.stamps_s(),
                                 tolerance_s, unmatched);
}

Trajectory ReadingsAtStamps(const Trajectory& readings, std::span<const double> stamps_s) {
  Trajectory out;
  out.Reserve(stamps_s.size());
  const std::vector<double>& stamps = readings.stamps_s();
  auto from = stamps.begin();
  for (double stamp : stamps_s) {
    from = std::lower_bound(from, stamps.end(), stamp);
    if (from == stamps.end() || *from != stamp) {
      throw InputError(
          fmt::format("no odometry reading at stamp {} s (readings cover {})", stamp, DescribeTimeRange(readings)));
    }
    out.Add(stamp, readings.poses()[static_cast<std::size_t>(from - stamps.begin())]);
  }
  return out;
}

}  // namespace slamsweep::evaluator::inline sequence
