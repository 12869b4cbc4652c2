#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "evaluator/formats/trajectory/carmen_log.h"
#include "evaluator/sequence/odometry_mode.h"
#include "evaluator/sequence/scan_stamps.h"
#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline sequence {

/// How a CARMEN log becomes a Sequence. Every field has a default that reads the Radish /
/// Freiburg "corrected" logs in shared/datasets.
struct CarmenSequenceOptions {
  /// Empty: the log's file name without ".gz", ".log" and ".clf".
  std::string name;
  /// Scan stamps come from each laser record's ipc_timestamp (the clock the relations files use),
  /// chosen under this policy; see ChooseScanStamps.
  StampOptions stamps;
  /// FLASER max range when set; otherwise PARAM robot_front_laser_max from the log; otherwise
  /// default_max_range_m. ROBOTLASER1 records state their own and are not overridden unless this is set.
  std::optional<double> max_range_m;
  /// CARMEN's own assumption for FLASER records (readlog.c: maximum_range = 80 m). The logs store
  /// "no return" as a reading at or beyond the sensor maximum (81.83 / 81.91 m in the SICK logs).
  double default_max_range_m = 80.0;
  /// Readings below this are not returns.
  double min_range_m = 0.0;
  /// The logged pose (FLASER x y theta, ROBOTLASER1 robot pose) is the SLAM-corrected pose in the
  /// "corrected" logs: keep it as Sequence::reference. Set false for raw logs, where it is odometry: then
  /// there is no reference, the records keep their file order (their acquisition order; late stamps are
  /// re-timed, StampRepair::kRetime) and relation stamps are moved onto the scans they name.
  bool logged_pose_is_reference = true;
  /// Build the scans from the RLASER records (the rear laser of old-style logs) instead of FLASER or
  /// ROBOTLASER1. Their fan is FLASER's, turned backwards: sensor pose on the robot (0, 0, yaw pi).
  /// Max range: max_range_m, else PARAM robot_rear_laser_max, else default_max_range_m.
  bool use_rear_laser = false;
  /// Kuemmerle et al. relations for this log, read into Sequence::relations when set.
  std::optional<std::filesystem::path> relations_path;
  /// The relations' clock on the log's: each relation stamp t becomes relations_rate * t +
  /// relations_offset_s (intel: the relations use absolute ipc time, the corrected log relative time;
  /// fr079: the relations' clock also runs at another rate). With recorded odometry the stamps are then
  /// moved onto the raw scans of the ODOM stream (MapRelationsOntoReadings).
  double relations_offset_s = 0.0;
  double relations_rate = 1.0;
  /// When set, only the relations with both stamps in [from, to] (on the relations' own clock, before
  /// the map above) are read; the others count as outside the log.
  std::optional<std::array<double, 2>> relations_window_s;
  /// How far a relation stamp may lie from the logged stamp of a reading to name that raw scan;
  /// unset: half the readings' median spacing, so each stamp names its nearest reading.
  std::optional<double> relations_match_tolerance_s;
  /// With logged_pose_is_reference: kRecorded rebuilds the robot's odometry from the ODOM stream
  /// (RebuildRecordedOdometry; scans then take the stamps of their raw readings, and every reading
  /// goes into Sequence::odometry_readings); kReference keeps the laser records' odometry fields.
  /// Logs that are not corrected logs have only their recorded odometry, whatever this says.
  OdometryMode odometry = OdometryMode::kReference;
  /// With kRecorded: a log without a usable stream is an InputError naming the line (true) or is
  /// read with its logged odometry and a warning saying so (false).
  bool require_recorded_odometry = true;
  /// When set, used as is; otherwise read from PROVENANCE.txt beside the log (ReadProvenanceBeside),
  /// else just the log's path as source.
  std::optional<Provenance> provenance;
};

/// Throws InputError naming the option for values out of range.
void CheckCarmenSequenceOptions(const CarmenSequenceOptions& options);

/// The scans of a parsed CARMEN log as a Sequence (no file access apart from relations/provenance
/// named in the options). Scans come from the FLASER records, or from the ROBOTLASER1 records when
/// the log has any (they state their beam geometry; CARMEN loggers that write both write the same
/// scan twice), or from the RLASER records when options.use_rear_laser. Geometry:
///   FLASER: FlaserBeamFan(n); sensor at the robot origin (the logged pose is the laser's pose,
///           which CARMEN's readlog.c calls laser_pose, so scans and reference agree);
///   RLASER: FlaserBeamFan(n) seen from a sensor at the robot origin facing backwards (yaw pi);
///   ROBOTLASER1: start_angle, angular_res, max_range of the record; sensor pose = laser pose in the
///           frame of the robot pose.
/// Odometry: FLASER odom_x/y/theta (ROBOTLASER1: robot pose), one pose per scan at the scan's stamp;
/// with options.odometry kRecorded on a corrected log, the rebuilt recorded odometry instead. A raw
/// robot log written by slamsweep gives its ODOM records as Sequence::odometry_readings.
/// Reference: the logged pose at the same stamps, when options.logged_pose_is_reference and the log is not
/// marked as a raw robot log ("PARAM slamsweep_logged_pose odometry", see FormatCarmenLog).
/// Warnings (each naming `source`) for repaired or made-up stamps, guessed beam fans, conflicting
/// PARAM values and ignored laser messages. A log without laser records, or a record that cannot
/// be a scan, is an InputError "FILE:LINE: ...".
Sequence CarmenLogToSequence(const CarmenLog& log, const std::filesystem::path& source,
                             const CarmenSequenceOptions& options = {});

/// ReadCarmenLog (plain or gzip) + CarmenLogToSequence.
Sequence ReadCarmenSequence(const std::filesystem::path& path, const CarmenSequenceOptions& options = {});

}  // namespace slamsweep::evaluator::inline sequence
