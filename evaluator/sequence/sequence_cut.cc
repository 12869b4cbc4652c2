#include "evaluator/sequence/sequence_cut.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <vector>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline sequence {
namespace {

/// The indices of `trajectory`'s poses stamped within [from_s, to_s].
std::vector<std::size_t> WithinSpan(const Trajectory& trajectory, double from_s, double to_s) {
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const double stamp = trajectory.stamps_s()[i];
    if (stamp >= from_s && stamp <= to_s) kept.push_back(i);
  }
  return kept;
}

}  // namespace

Sequence KeepScanRange(Sequence sequence, std::size_t first, std::size_t count) {
  first = std::min(first, sequence.scans.size());
  count = std::min(count, sequence.scans.size() - first);
  if (count == 0) throw InputError(fmt::format("sequence '{}': the cut keeps no scan", sequence.name));
  if (first == 0 && count == sequence.scans.size()) return sequence;
  sequence.scans.erase(sequence.scans.begin() + static_cast<std::ptrdiff_t>(first + count), sequence.scans.end());
  sequence.scans.erase(sequence.scans.begin(), sequence.scans.begin() + static_cast<std::ptrdiff_t>(first));
  std::vector<std::size_t> kept(count);
  std::iota(kept.begin(), kept.end(), first);
  sequence.odometry = std::move(sequence.odometry).Select(kept);
  // A cut that keeps the first scan keeps what came before it, as the uncut sequence does.
  const double from_s = first == 0 ? -std::numeric_limits<double>::infinity() : sequence.scans.front().stamp_s;
  const double to_s = sequence.scans.back().stamp_s;
  if (!sequence.odometry_readings.empty()) {
    sequence.odometry_readings =
        std::move(sequence.odometry_readings).Select(WithinSpan(sequence.odometry_readings, from_s, to_s));
  }
  if (sequence.reference) {
    sequence.reference = std::move(*sequence.reference).Select(WithinSpan(*sequence.reference, from_s, to_s));
    if (sequence.reference->empty()) sequence.reference.reset();
  }
  KeepRelationsInsideLog(sequence);
  return sequence;
}

Sequence KeepTimeSpan(Sequence sequence, double from_s, double to_s) {
  const auto by_stamp = [](const LaserScan& scan, double stamp) { return scan.stamp_s < stamp; };
  auto begin = std::upper_bound(sequence.scans.begin(), sequence.scans.end(), from_s,
                                [](double stamp, const LaserScan& scan) { return stamp < scan.stamp_s; });
  if (begin != sequence.scans.begin()) --begin;  // the last scan at or before from_s
  auto end = std::lower_bound(begin, sequence.scans.end(), to_s, by_stamp);
  if (end != sequence.scans.end()) ++end;  // through the first scan at or after to_s
  const bool misses =
      sequence.scans.empty() || to_s < sequence.scans.front().stamp_s || from_s > sequence.scans.back().stamp_s;
  if (misses || begin == end) {
    throw InputError(
        fmt::format("sequence '{}': no scan between {:.6f} and {:.6f} s (its scans span {:.6f} to {:.6f} s)",
                    sequence.name, from_s, to_s, sequence.scans.empty() ? 0.0 : sequence.scans.front().stamp_s,
                    sequence.scans.empty() ? 0.0 : sequence.scans.back().stamp_s));
  }
  const auto first = static_cast<std::size_t>(begin - sequence.scans.begin());
  const auto count = static_cast<std::size_t>(end - begin);
  return KeepScanRange(std::move(sequence), first, count);
}

}  // namespace slamsweep::evaluator::inline sequence
