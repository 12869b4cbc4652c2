#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "evaluator/core/relation.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/formats/trajectory/carmen_log.h"
#include "evaluator/sequence/scan_stamps.h"

namespace slamsweep::evaluator::inline sequence {

/// The robot's wheel odometry as a corrected CARMEN log keeps it. Besides its laser records
/// (keyframes, logged at the SLAM-corrected pose), such a log holds one ODOM "reading" per raw laser
/// scan of the original run, logged as the corrected pose of the last keyframe composed with the raw
/// odometry increment since that keyframe, and one "reset" ODOM right after each keyframe that
/// repeats its corrected pose. Chaining the increments keyframe to keyframe gives the odometry.
struct RecordedOdometry {
  /// The robot's odometry at every reading, in file order, on strictly increasing stamps (the logged
  /// ones repaired by the stamp policy). The first readings (before the first keyframe) are the
  /// logged poses themselves; the chain continues from there.
  Trajectory readings;
  /// The stamps as logged (they may repeat or step back), parallel to `readings`.
  std::vector<double> logged_stamps_s;
  /// Line of each reading in the log.
  std::vector<std::size_t> lines;
  /// For each laser record given: the index of its reading (the last reading before it, which the
  /// logger wrote for the same raw scan).
  std::vector<std::size_t> scan_readings;
  /// ODOM records recognised as resets (by position and pose, never by stamp).
  std::size_t resets = 0;
  /// How the reading stamps were chosen, and how many were lifted to keep their order strict.
  StampOutcome stamp_outcome = StampOutcome::kRecorded;
  std::size_t repaired_stamps = 0;
  /// Each naming the log: the stamp repairs.
  std::vector<std::string> warnings;
};

/// The stamp options for a reading stream. The corrected logs print stamps with six significant
/// digits, so bursts of readings share a printed stamp (intel: 2,459 of 13,631) and the raw run's
/// stamps step back now and then (629 times): up to half of the stamps may be lifted before the
/// stream counts as having no clock (then it is stamped in record order, like its scans).
StampOptions ReadingStampOptions(const StampOptions& scan_options);

/// Rebuilds the odometry of `log` for its laser records `scans` (in file order). A reset is an ODOM
/// right after a laser record, with the record's logged pose (1 um, 1 urad). Throws InputError
/// "FILE:LINE: ..." when the log has no such stream: an ODOM after a laser record that is not its
/// pose, or a laser record without a reading since the previous one.
RecordedOdometry RebuildRecordedOdometry(const CarmenLog& log, std::span<const CarmenLaserRecord* const> scans,
                                         const std::filesystem::path& source, const StampOptions& stamps);

/// Moves each relation stamp onto the reading whose logged stamp is nearest to it (within
/// tolerance_s; the first in file order among equal stamps) and gives it that reading's stamp, so
/// that relations name raw scans even where the reading stamps had to be repaired. A stamp with
/// no reading that near keeps its value; `unmatched` counts them.
Relations MapRelationsOntoReadings(Relations relations, const RecordedOdometry& odometry, double tolerance_s,
                                   std::size_t& unmatched);

/// The poses of `readings` whose stamps are `stamps_s` (ascending; each must be one of the readings'
/// stamps, as scan stamps are in a log with recorded odometry). InputError naming the first stamp
/// that is not.
Trajectory ReadingsAtStamps(const Trajectory& readings, std::span<const double> stamps_s);

}  // namespace slamsweep::evaluator::inline sequence
