#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "evaluator/core/trajectory.h"
#include "evaluator/formats/trajectory/carmen_log.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {

/// How far a CARMEN log's clock is trusted. Many Radish logs have broken ipc_timestamps:
/// constant or zero (campus, orebro, belgioioso), printed with 6 significant digits so that
/// nearly all are equal (mit-csail: 1.13486e+09), or wrapped (infinite-corridor jumps from
/// -1.82 s to 4.29e9 s, a 32-bit wrap). The Intel log, whose stamps are good, still steps
/// back in time 4 times in 909 steps (by up to 0.86 s); those stamps are kept.
struct CarmenReadOptions {
  /// Spacing of the stamps given by record order when the log's own are unusable.
  double record_order_period_s = 1.0;
  /// A step between consecutive laser records larger than this (either sign) is a wrapped or
  /// corrupt clock, not a pause in logging.
  double max_plausible_step_s = 3600.0;
  /// The stamps are unusable when more than this share of consecutive steps does not
  /// increase (repeats or goes back): time association could not tell those scans apart.
  double max_non_increasing_fraction = 0.01;
};

/// Checks the options against each other and against sense; throws InputError naming the option.
void ValidateCarmenReadOptions(const CarmenReadOptions& options);

/// The trajectory of a CARMEN log and what the reader had to decide on the way.
struct CarmenPoses {
  /// One pose per laser record: the FLASER robot pose (x y theta) or, in a log without FLASER
  /// records, the ROBOTLASER1 robot_pose. Stamps are ipc_timestamps, or, when used_record_order,
  /// record index * record_order_period_s (0, 1, 2, ... s by default).
  Trajectory trajectory;
  /// Human-readable notes, each naming the file: why record order was used, out-of-order stamps
  /// that were kept, ROBOTLASER1 records ignored beside FLASER ones.
  std::vector<std::string> warnings;
  bool used_record_order = false;
};

/// Throws InputError when the log holds no FLASER or ROBOTLASER1 record.
CarmenPoses CarmenPosesFromLog(const CarmenLog& log, const std::filesystem::path& source,
                               const CarmenReadOptions& options = {});
/// Reads a plain or gzip CARMEN log (.log, .log.gz, .clf).
CarmenPoses ReadCarmenPoses(const std::filesystem::path& path, const CarmenReadOptions& options = {});

/// Writes one FLASER record with no beams per pose (x y theta twice, the stamp as ipc and
/// logger timestamp, host "slamsweep"): a log that ReadCarmenPoses reads back. Poses must be
/// planar (else InputError naming the pose).
void WriteCarmenPoses(const Trajectory& trajectory, std::ostream& out);
void WriteCarmenPoses(const Trajectory& trajectory, const std::filesystem::path& path);

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
