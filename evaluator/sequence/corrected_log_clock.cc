#include "evaluator/sequence/corrected_log_clock.h"

#include <fmt/format.h>

#include <algorithm>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline sequence {

void TakeClockFromCorrectedLog(Sequence& sequence, Sequence corrected, std::size_t first_scan,
                               std::size_t first_reading, std::size_t every,
                               const std::filesystem::path& corrected_source) {
  const Trajectory& readings = corrected.odometry_readings;
  if (readings.empty()) {
    throw InputError(Located(corrected_source, 0,
                             "corrected_log: the log has no recorded odometry stream, so no raw-scan clock to give "
                             "sequence '" +
                                 sequence.name + "'"));
  }
  if (every == 0) throw InputError("corrected_log.every: expected a step of at least 1 reading, got 0");
  if (first_scan >= sequence.scans.size()) {
    throw InputError(fmt::format("corrected_log.first_scan: sequence '{}' has {} scans, got first_scan {}",
                                 sequence.name, sequence.scans.size(), first_scan));
  }
  if (first_scan > 0) {
    const auto drop = static_cast<std::ptrdiff_t>(first_scan);
    sequence.scans.erase(sequence.scans.begin(), sequence.scans.begin() + drop);
    sequence.odometry =
        Trajectory(std::vector<double>(sequence.odometry.stamps_s().begin() + drop, sequence.odometry.stamps_s().end()),
                   std::vector<Pose>(sequence.odometry.poses().begin() + drop, sequence.odometry.poses().end()));
    sequence.warnings.push_back(
        fmt::format("sequence '{}': its first {} scan(s) come before the corrected log's run "
                    "(corrected_log.first_scan) and were dropped",
                    sequence.name, first_scan));
  }
  const std::size_t count = sequence.scans.size();
  if (count == 0) return;
  const std::size_t last_reading = first_reading + every * (count - 1);
  if (last_reading >= readings.size()) {
    throw InputError(
        Located(corrected_source, 0,
                fmt::format("corrected_log: sequence '{}' has {} scans, which need reading {} (first_reading "
                            "{} + every {} x {}); the log has {} readings",
                            sequence.name, count, last_reading, first_reading, every, count - 1, readings.size())));
  }
  Trajectory odometry;
  odometry.Reserve(count);
  for (std::size_t j = 0; j < count; ++j) {
    const double stamp = readings.stamps_s()[first_reading + every * j];
    sequence.scans[j].stamp_s = stamp;
    odometry.Add(stamp, sequence.odometry.poses()[j]);
  }
  sequence.odometry = std::move(odometry);

  // The scans both logs hold: the same raw scan must have the same ranges.
  std::size_t shared = 0;
  for (const LaserScan& scan : corrected.scans) {
    const auto found = std::lower_bound(sequence.scans.begin(), sequence.scans.end(), scan.stamp_s,
                                        [](const LaserScan& a, double stamp) { return a.stamp_s < stamp; });
    if (found == sequence.scans.end() || found->stamp_s != scan.stamp_s) continue;
    if (found->ranges_m != scan.ranges_m) {
      throw InputError(Located(
          corrected_source, 0,
          fmt::format("corrected_log: scan {} of sequence '{}' and the corrected log's scan at {} s are the same raw "
                      "scan by the time map (first_scan {}, first_reading {}, every {}), but their ranges differ: the "
                      "map is wrong",
                      first_scan + static_cast<std::size_t>(found - sequence.scans.begin()), sequence.name,
                      scan.stamp_s, first_scan, first_reading, every)));
    }
    ++shared;
  }
  sequence.warnings.push_back(Located(
      corrected_source, 0,
      fmt::format(
          "scan stamps taken from the corrected log's recorded ODOM readings (scan {} + j = reading {} + {} j); "
          "{} scans held by both logs have identical ranges",
          first_scan, first_reading, every, shared)));
  sequence.warnings.insert(sequence.warnings.end(), corrected.warnings.begin(), corrected.warnings.end());
  sequence.reference = std::move(corrected.reference);
  sequence.relations = std::move(corrected.relations);
  sequence.relations_outside_log += corrected.relations_outside_log;
}

}  // namespace slamsweep::evaluator::inline sequence
