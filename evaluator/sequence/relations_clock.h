#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/relation.h"
#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline sequence {

/// The map t_log = rate * t_relations + offset_s between a relations file's clock and a log's, fitted
/// from time stamps alone: each relation stamp names a raw scan, whose time the log's reading stamps
/// carry. Never fitted to any trajectory's error.
struct RelationsClockFit {
  double offset_s = 0.0;
  double rate = 1.0;
  /// Distinct relation stamps, those within the tolerance of a reading after the fit (the fit's
  /// pairs), and those within 10 ms (exact matches: a log whose readings carry the laser's clock
  /// matches them all, as intel does).
  std::size_t stamps = 0;
  std::size_t matched = 0;
  std::size_t matched_within_10ms = 0;
  /// The tolerance used: half the readings' median spacing, so each relation stamp pairs with one reading.
  double tolerance_s = 0.0;
  /// Residuals (reading stamp - mapped relation stamp) of the matched stamps.
  double rms_residual_s = 0.0;
  double max_abs_residual_s = 0.0;
  /// The offset's drift over the relations' span that the rate takes up: (rate - 1) * span.
  double drift_over_span_s = 0.0;

  nlohmann::json ToJson() const;
};

struct RelationsClockFitOptions {
  /// Width of the histogram bins in which the coarse offset is the most frequent difference.
  double coarse_bin_s = 0.02;
  /// Where the least squares start instead of the histogram's offset (rate 1): the odometry fit's
  /// map, on a log whose stamps alone fit every multiple of the laser period (FitRelationsClockByOdometry).
  std::optional<double> start_offset_s;
  double start_rate = 1.0;
};

/// Fits the clock map: the most frequent difference between a reading stamp and a relation stamp
/// (histogram of all pairs, two neighbouring bins together; or options.start_offset_s) gives the
/// offset; then least squares
/// over each relation stamp's nearest reading, within half the readings' median spacing, refine
/// offset and rate (three rounds). Throws InputError when either list is empty or fewer than two
/// stamps match.
RelationsClockFit FitRelationsClock(std::span<const double> relation_stamps_s, std::span<const double> reading_stamps_s,
                                    const RelationsClockFitOptions& options = {});

/// A map found by searching the offset at which the relations disagree least with a measurement
/// of the robot's (every 10 ms, then every 1 ms), the rate from the offsets fitted to the first and
/// second half of the relations. The measurements are robot data, the same for every program; no SLAM
/// result enters.
struct SearchedClockFit {
  double offset_s = 0.0;
  double rate = 1.0;
  /// The relations searched over.
  std::size_t relations = 0;
  /// The disagreement at the fitted offset, and the lowest one found more than 0.1 s away from it
  /// (the margin by which the fit is unambiguous), in `unit`.
  double disagreement = 0.0;
  double next_best_disagreement = 0.0;
  std::string unit;
  /// The offsets fitted to each half (at its middle relation stamp).
  double first_half_offset_s = 0.0;
  double second_half_offset_s = 0.0;

  nlohmann::json ToJson() const;
};

/// The map from the recorded odometry, for logs whose reading stamps do not carry the laser's clock
/// (fr079: the relation stamps tick at a regular 0.85 s, the readings jitter by up to 0.1 s, so stamps
/// alone fit equally well at every multiple of the laser period): the offset under which the rotations
/// of the short relations (spans up to the median span) agree best with the rotation the odometry
/// measured over the same interval (mean absolute difference, deg), over the offsets that put the
/// relations inside the readings' span. A lag of the readings behind the laser moves it by the whole
/// lag. Throws InputError when the readings or the short relations are too few, or no offset puts the
/// relations inside the readings.
SearchedClockFit FitRelationsClockByOdometry(const Relations& relations, const Trajectory& readings);

/// The map from the laser. Kuemmerle et al. made the relations by matching these very scans, so at the
/// right map each relation lays the scan at its second stamp onto the scan at its first. The fit is
/// the offset where that overlay is closest (root mean squared distance, cm, from each placed hit to
/// the nearest hit, capped at 10 cm, over all relations; each stamp takes its nearest scan, and the
/// odometry `readings` move the relation's ends from the mapped stamps to those scans'), within
/// `search_s` of `start_offset_s`. The odometry spans only the fraction of a scan period between a
/// stamp and its scan, so a lag of its readings hardly moves this fit. `scans` in time order, stamps
/// on the log's clock. Throws InputError for fewer than 2 scans or 4 relations, stamps that do not
/// increase, or no offset in the window that puts a relation on the scans.
SearchedClockFit FitRelationsClockByScans(const Relations& relations, std::span<const LaserScan> scans,
                                          const Trajectory& readings, double start_offset_s, double search_s = 0.5);

}  // namespace slamsweep::evaluator::inline sequence
