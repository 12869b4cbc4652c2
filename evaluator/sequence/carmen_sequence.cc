#include "evaluator/sequence/carmen_sequence.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/trajectory/relations_format.h"
#include "evaluator/sequence/flaser_fan.h"
#include "evaluator/sequence/odometry_direction.h"
#include "evaluator/sequence/provenance_file.h"
#include "evaluator/sequence/record_order_check.h"
#include "evaluator/sequence/recorded_odometry.h"
#include "evaluator/sequence/relation_stamps.h"
#include "evaluator/sequence/robot_log.h"

namespace slamsweep::evaluator::inline sequence {
namespace {

constexpr std::string_view kFlaser = "FLASER";
constexpr std::string_view kRearLaser = "RLASER";
constexpr std::string_view kRobotLaser = "ROBOTLASER1";
constexpr std::string_view kFrontLaserMaxParam = "robot_front_laser_max";
constexpr std::string_view kRearLaserMaxParam = "robot_rear_laser_max";
/// The rear laser of CARMEN's old-style logs is mounted facing backwards: its fan is the front
/// laser's turned by half a turn.
constexpr double kRearLaserYawRad = 3.14159265358979323846;
/// How many line numbers a warning lists before it says "...".
constexpr std::size_t kLinesShown = 5;

std::string DefaultName(const std::filesystem::path& source) {
  std::string name = source.filename().string();
  for (std::string_view suffix : {".gz", ".log", ".clf"}) {
    if (name.size() > suffix.size() && name.ends_with(suffix)) name.resize(name.size() - suffix.size());
  }
  return name;
}

std::string LineList(const std::vector<std::size_t>& lines) {
  std::string text;
  for (std::size_t i = 0; i < lines.size() && i < kLinesShown; ++i) {
    if (i > 0) text += ", ";
    text += std::to_string(lines[i]);
  }
  if (lines.size() > kLinesShown) text += ", ...";
  return text;
}

/// The FLASER/RLASER max range: the option, else the log's last `param_name` PARAM
/// (robot_front_laser_max / robot_rear_laser_max), else the default.
bool MarkedAsRawRobotLog(const CarmenLog& log) {
  return std::any_of(log.params.begin(), log.params.end(), [](const CarmenParam& param) {
    return param.name == kCarmenLoggedPoseParam && param.value == kCarmenLoggedPoseOdometry;
  });
}

double FlaserMaxRange(const CarmenLog& log, const std::filesystem::path& source, const CarmenSequenceOptions& options,
                      std::string_view param_name, std::vector<std::string>& warnings) {
  if (options.max_range_m) return *options.max_range_m;
  std::optional<double> from_param;
  std::size_t from_line = 0;
  for (const CarmenParam& param : log.params) {
    if (param.name != param_name) continue;
    double value = 0.0;
    const char* begin = param.value.data();
    const char* end = begin + param.value.size();
    const auto [stop, error] = std::from_chars(begin, end, value);
    if (error != std::errc() || stop != end || !std::isfinite(value) || !(value > options.min_range_m)) {
      throw InputError(Located(source, param.line,
                               fmt::format("PARAM {}: expected a range in metres above min_range_m ({}), got '{}'",
                                           param_name, options.min_range_m, param.value)));
    }
    if (from_param && *from_param != value) {
      warnings.push_back(Located(source, param.line,
                                 fmt::format("PARAM {} = {} replaces {} set on line {}; the last value is used",
                                             param_name, value, *from_param, from_line)));
    }
    from_param = value;
    from_line = param.line;
  }
  return from_param.value_or(options.default_max_range_m);
}

/// The laser records' ipc_timestamps in file order.
std::vector<double> RecordedStamps(const std::vector<const CarmenLaserRecord*>& records) {
  std::vector<double> recorded;
  recorded.reserve(records.size());
  for (const CarmenLaserRecord* record : records) recorded.push_back(record->ipc_stamp_s);
  return recorded;
}

/// Strictly increasing scan stamps for the records (their stamps `recorded`), with a warning when they
/// had to change.
ScanStamps ScanStampsOf(const std::vector<const CarmenLaserRecord*>& records, const std::vector<double>& recorded,
                        const std::filesystem::path& source, const StampOptions& options,
                        std::vector<std::string>& warnings) {
  ScanStamps stamps = ChooseScanStamps(recorded, options);
  if (stamps.non_increasing.empty()) return stamps;

  const std::size_t first = stamps.non_increasing.front();
  if (options.policy == StampPolicy::kRecorded) {
    throw InputError(Located(source, records[first]->line,
                             fmt::format("ipc_timestamp {} does not come after the previous scan's {} (stamp policy "
                                         "'recorded'; 'auto' repairs such stamps or falls back to record order)",
                                         recorded[first], recorded[first - 1])));
  }
  if (stamps.outcome == StampOutcome::kRepaired) {
    std::vector<std::size_t> lines;
    for (std::size_t index : stamps.non_increasing) lines.push_back(records[index]->line);
    warnings.push_back(
        Located(source, 0,
                fmt::format("{} of {} scan stamps did not come after the previous one and were lifted to it + {} s "
                            "(lines {})",
                            stamps.non_increasing.size(), records.size(), options.repair_step_s, LineList(lines))));
  } else if (stamps.outcome == StampOutcome::kRetimed) {
    const StampFacts facts = DescribeStamps(recorded, stamps);
    std::vector<std::size_t> lines;
    for (std::size_t index : stamps.retimed) lines.push_back(records[index]->line);
    warnings.push_back(Located(
        source, 0,
        fmt::format("{} of {} scan stamps do not come after the previous one ({} step back, by up to {:.3f} s; {} "
                    "repeat it); the scans stay in file order and {} stamps outside the longest increasing run were "
                    "re-timed between their neighbours, by up to {:.3f} s (lines {})",
                    stamps.non_increasing.size(), records.size(), facts.steps_back, facts.largest_step_back_s,
                    facts.duplicates, stamps.retimed.size(), facts.largest_change_s, LineList(lines))));
  } else if (stamps.outcome == StampOutcome::kRecordOrder && options.policy == StampPolicy::kAuto) {
    const auto [low, high] = std::minmax_element(recorded.begin(), recorded.end());
    warnings.push_back(Located(
        source, 0,
        fmt::format("recorded scan stamps are unusable ({} of {} do not come after the previous one, first on line {}; "
                    "they span [{}, {}] s); scans are stamped in record order every {} s instead",
                    stamps.non_increasing.size(), records.size(), records[first]->line, *low, *high,
                    options.record_order_period_s)));
  }
  return stamps;
}

LaserScan FlaserScan(const CarmenLaserRecord& record, const std::filesystem::path& source, double max_range_m,
                     bool& known_layout) {
  BeamFan fan;
  try {
    fan = FlaserBeamFan(record.ranges_m.size());
  } catch (const InputError& error) {
    throw InputError(Located(source, record.line, error.what()));
  }
  known_layout = fan.known_layout;
  LaserScan scan;
  scan.angle_min_rad = fan.angle_min_rad;
  scan.angle_increment_rad = fan.angle_increment_rad;
  scan.range_max_m = max_range_m;
  return scan;
}

LaserScan RobotLaserScan(const CarmenLaserRecord& record, const std::filesystem::path& source,
                         const CarmenSequenceOptions& options) {
  const CarmenBeamGeometry geometry = record.geometry.value_or(CarmenBeamGeometry{});
  if (record.ranges_m.empty()) throw InputError(Located(source, record.line, "ROBOTLASER1 with no readings"));
  if (geometry.angular_resolution_rad == 0.0) {
    throw InputError(Located(source, record.line, "ROBOTLASER1 angular_res: expected a non-zero beam spacing, got 0"));
  }
  LaserScan scan;
  scan.angle_min_rad = geometry.start_angle_rad;
  scan.angle_increment_rad = geometry.angular_resolution_rad;
  scan.range_max_m = options.max_range_m.value_or(geometry.max_range_m);
  if (!(scan.range_max_m > options.min_range_m)) {
    throw InputError(Located(source, record.line,
                             fmt::format("ROBOTLASER1 max_range: expected a range above min_range_m ({}), got {}",
                                         options.min_range_m, scan.range_max_m)));
  }
  scan.sensor_pose_on_robot = Relative(record.robot_pose, record.laser_pose);
  return scan;
}

/// Laser records of each type that are not in the sequence.
struct IgnoredLasers {
  std::size_t flaser = 0;
  std::size_t rlaser = 0;
  std::size_t robot_laser = 0;
};

void WarnAboutIgnoredLasers(const CarmenLog& log, const std::filesystem::path& source, std::string_view used_type,
                            const IgnoredLasers& ignored, std::vector<std::string>& warnings) {
  if (ignored.flaser > 0) {
    warnings.push_back(Located(
        source, 0,
        used_type == kRobotLaser
            ? fmt::format("{} FLASER records ignored: the log also has ROBOTLASER1 records, which state their beam "
                          "geometry",
                          ignored.flaser)
            : fmt::format("{} FLASER records ignored (the sequence is built from the {} records)", ignored.flaser,
                          used_type)));
  }
  if (ignored.robot_laser > 0) {
    warnings.push_back(Located(source, 0,
                               fmt::format("{} ROBOTLASER1 records ignored (the sequence is built from the {} records)",
                                           ignored.robot_laser, used_type)));
  }
  if (ignored.rlaser > 0) {
    warnings.push_back(Located(
        source, 0,
        fmt::format("{} RLASER records ignored (the rear laser; set use_rear_laser to read it)", ignored.rlaser)));
  }
  for (const auto& [type, count] : log.skipped_messages) {
    if (type.find("LASER") == std::string::npos) continue;
    warnings.push_back(
        Located(source, 0, fmt::format("{} {} records ignored (only the front or rear laser is read)", count, type)));
  }
}

Relations ShiftedRelations(Relations relations, double rate, double offset_s) {
  for (Relation& relation : relations) {
    relation.t1_s = rate * relation.t1_s + offset_s;
    relation.t2_s = rate * relation.t2_s + offset_s;
  }
  return relations;
}

/// The ODOM records of a raw robot log written by slamsweep, when their stamps strictly increase
/// (the readings between its scans); empty otherwise.
Trajectory RawLogReadings(const CarmenLog& log) {
  Trajectory readings;
  readings.Reserve(log.odometry.size());
  for (const CarmenOdomRecord& odom : log.odometry) {
    if (!readings.empty() && !(odom.ipc_stamp_s > readings.stamps_s().back())) return Trajectory();
    readings.Add(odom.ipc_stamp_s, odom.pose);
  }
  return readings;
}

/// Whether every scan stamp is one of the readings' stamps (the Sequence invariant for readings).
bool ReadingsHoldScanStamps(const Trajectory& readings, const std::vector<double>& scan_stamps_s) {
  return std::includes(readings.stamps_s().begin(), readings.stamps_s().end(), scan_stamps_s.begin(),
                       scan_stamps_s.end());
}

Provenance ProvenanceOf(const std::filesystem::path& source, const CarmenSequenceOptions& options) {
  if (options.provenance) return *options.provenance;
  Provenance provenance = ReadProvenanceBeside(source).value_or(Provenance{source.string(), "", "", ""});
  if (options.relations_path) {
    if (const std::optional<Provenance> relations = ReadProvenanceBeside(*options.relations_path);
        relations && !relations->citation.empty()) {
      provenance.citation +=
          (provenance.citation.empty() ? "" : "; ") + std::string("relations: ") + relations->citation;
    }
  }
  return provenance;
}

/// Where the log's odometry stream writes every step forward, gives back the steps the scans say the
/// robot backed up (odometry_direction.h), re-reads each scan's odometry and says what was done.
void RestoreRecordedReversing(RecordedOdometry& recorded, const std::filesystem::path& source, Sequence& sequence) {
  const ReversingRepair repair = RestoreReversing(recorded.readings, recorded.scan_readings, sequence.scans);
  if (!repair.unsigned_stream) return;
  std::vector<Pose> poses;
  poses.reserve(recorded.scan_readings.size());
  for (std::size_t reading : recorded.scan_readings) poses.push_back(recorded.readings.poses()[reading]);
  sequence.odometry = Trajectory(sequence.odometry.stamps_s(), std::move(poses));
  sequence.warnings.push_back(Located(
      source, 0,
      fmt::format("recorded odometry: not one of its {} moving ODOM steps goes backward (the log writes distances "
                  "without their sign); the scans say the robot backed up over {} of {} scan steps tested, whose "
                  "odometry now moves backward",
                  repair.moving_steps, repair.scan_steps_reversed, repair.scan_steps_tested)));
}

}  // namespace

void CheckCarmenSequenceOptions(const CarmenSequenceOptions& options) {
  CheckStampOptions(options.stamps);
  if (!(options.min_range_m >= 0.0) || !std::isfinite(options.min_range_m)) {
    throw InputError(fmt::format("min_range_m: expected a finite range >= 0 m, got {}", options.min_range_m));
  }
  if (!(options.default_max_range_m > options.min_range_m) || !std::isfinite(options.default_max_range_m)) {
    throw InputError(fmt::format("default_max_range_m: expected a finite range above min_range_m ({} m), got {}",
                                 options.min_range_m, options.default_max_range_m));
  }
  if (options.max_range_m && (!(*options.max_range_m > options.min_range_m) || !std::isfinite(*options.max_range_m))) {
    throw InputError(fmt::format("max_range_m: expected a finite range above min_range_m ({} m), got {}",
                                 options.min_range_m, *options.max_range_m));
  }
  if (!(options.relations_rate > 0.0) || !std::isfinite(options.relations_rate)) {
    throw InputError(fmt::format("relations_rate: expected a finite rate > 0, got {}", options.relations_rate));
  }
  if (options.relations_match_tolerance_s &&
      (!(*options.relations_match_tolerance_s >= 0.0) || !std::isfinite(*options.relations_match_tolerance_s))) {
    throw InputError(fmt::format("relations_match_tolerance_s: expected a finite tolerance >= 0 s, got {}",
                                 *options.relations_match_tolerance_s));
  }
  if (!std::isfinite(options.relations_offset_s)) {
    throw InputError(
        fmt::format("relations_offset_s: expected a finite offset in seconds, got {}", options.relations_offset_s));
  }
}

Sequence CarmenLogToSequence(const CarmenLog& log, const std::filesystem::path& source,
                             const CarmenSequenceOptions& options) {
  CheckCarmenSequenceOptions(options);
  const bool use_robot_laser = !options.use_rear_laser &&
                               std::any_of(log.lasers.begin(), log.lasers.end(),
                                           [](const CarmenLaserRecord& record) { return record.type == kRobotLaser; });
  const std::string_view used_type = options.use_rear_laser ? kRearLaser : use_robot_laser ? kRobotLaser : kFlaser;
  std::vector<const CarmenLaserRecord*> records;
  IgnoredLasers ignored;
  for (const CarmenLaserRecord& record : log.lasers) {
    if (record.type == used_type) {
      records.push_back(&record);
    } else if (record.type == kFlaser) {
      ++ignored.flaser;
    } else if (record.type == kRearLaser) {
      ++ignored.rlaser;
    } else {
      ++ignored.robot_laser;
    }
  }
  if (records.empty()) {
    throw InputError(Located(source, 0,
                             options.use_rear_laser
                                 ? "no RLASER records (option use_rear_laser): a sequence needs laser scans"
                                 : "no FLASER or ROBOTLASER1 records: a sequence needs laser scans"));
  }

  Sequence sequence;
  sequence.name = options.name.empty() ? DefaultName(source) : options.name;
  WarnAboutIgnoredLasers(log, source, used_type, ignored, sequence.warnings);
  // A raw robot log (a program input slamsweep wrote) logs odometry, never a corrected pose.
  const bool logged_pose_is_reference = options.logged_pose_is_reference && !MarkedAsRawRobotLog(log);
  const double flaser_max_range_m = FlaserMaxRange(
      log, source, options, options.use_rear_laser ? kRearLaserMaxParam : kFrontLaserMaxParam, sequence.warnings);
  std::optional<RecordedOdometry> recorded;
  if (options.odometry == OdometryMode::kRecorded && logged_pose_is_reference) {
    try {
      recorded = RebuildRecordedOdometry(log, records, source, options.stamps);
    } catch (const InputError& error) {
      if (options.require_recorded_odometry) throw;
      sequence.warnings.push_back(std::string(error.what()) +
                                  "; the laser records' odometry (the reference) is used instead");
    }
  }
  std::vector<double> stamps_s;
  const std::vector<double> recorded_stamps_s = RecordedStamps(records);
  if (recorded) {
    // Each scan is stamped like its raw reading, so that scans, readings and relations share one clock.
    stamps_s.reserve(records.size());
    for (std::size_t reading : recorded->scan_readings) stamps_s.push_back(recorded->readings.stamps_s()[reading]);
    sequence.warnings.insert(sequence.warnings.end(), recorded->warnings.begin(), recorded->warnings.end());
  } else {
    StampOptions stamp_options = options.stamps;
    // A raw log's records are in the order they were taken while some stamps arrived late (the full-rate
    // intel run: see RecordOrderCheck): each late stamp is re-timed alone, the records keep their order.
    if (!logged_pose_is_reference) stamp_options.repair = StampRepair::kRetime;
    const ScanStamps chosen = ScanStampsOf(records, recorded_stamps_s, source, stamp_options, sequence.warnings);
    sequence.stamp_facts = DescribeStamps(recorded_stamps_s, chosen);
    stamps_s = chosen.stamps_s;
  }

  std::vector<std::size_t> guessed_fan_lines;
  sequence.scans.reserve(records.size());
  sequence.odometry.Reserve(records.size());
  Trajectory reference;
  // ROBOTLASER1 carries the (corrected) robot pose but no odometry: that comes from the ODOM
  // record logged before it. Without ODOM records the robot pose has to serve as both.
  const bool odometry_from_odom = use_robot_laser && !log.odometry.empty();
  if (use_robot_laser && log.odometry.empty() && logged_pose_is_reference) {
    sequence.warnings.push_back(Located(source, 0,
                                        "ROBOTLASER1 log without ODOM records: the odometry is the logged robot pose, "
                                        "which is also the reference, so odometry and reference are the same"));
  }
  std::size_t next_odom = 0;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const CarmenLaserRecord& record = *records[i];
    Pose odometry_pose = record.odom_pose;
    if (recorded) {
      odometry_pose = recorded->readings.poses()[recorded->scan_readings[i]];
    } else if (odometry_from_odom) {
      while (next_odom < log.odometry.size() && log.odometry[next_odom].line < record.line) ++next_odom;
      // The latest ODOM before this scan; a scan before the first ODOM takes the first one.
      odometry_pose = log.odometry[next_odom == 0 ? 0 : next_odom - 1].pose;
    }
    LaserScan scan;
    if (use_robot_laser) {
      scan = RobotLaserScan(record, source, options);
    } else {
      bool known_layout = true;
      scan = FlaserScan(record, source, flaser_max_range_m, known_layout);
      if (options.use_rear_laser) scan.sensor_pose_on_robot = Pose::Planar(0.0, 0.0, kRearLaserYawRad);
      if (!known_layout) guessed_fan_lines.push_back(record.line);
    }
    scan.stamp_s = stamps_s[i];
    scan.range_min_m = options.min_range_m;
    scan.ranges_m.assign(record.ranges_m.begin(), record.ranges_m.end());
    sequence.scans.push_back(std::move(scan));
    sequence.odometry.Add(stamps_s[i], odometry_pose);
    if (logged_pose_is_reference) reference.Add(stamps_s[i], record.robot_pose);
  }
  if (recorded) RestoreRecordedReversing(*recorded, source, sequence);
  if (sequence.stamp_facts && !logged_pose_is_reference && sequence.stamp_facts->steps_back > 0) {
    sequence.stamp_facts->order_check = CheckRecordOrder(sequence.scans, sequence.odometry.poses(), recorded_stamps_s);
  }
  if (!guessed_fan_lines.empty()) {
    sequence.warnings.push_back(Located(
        source, 0,
        fmt::format("{} {} records have a beam count that is not a SICK layout (180, 181, 360, 361); their beams "
                    "were spread over 180 deg as CARMEN does (lines {})",
                    guessed_fan_lines.size(), used_type, LineList(guessed_fan_lines))));
  }
  if (logged_pose_is_reference) sequence.reference = std::move(reference);
  if (options.relations_path) {
    Relations relations = ReadRelations(*options.relations_path);
    if (options.relations_window_s) {
      // Named values, not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
      const double from_s = (*options.relations_window_s)[0];
      const double to_s = (*options.relations_window_s)[1];
      const std::size_t before = relations.size();
      std::erase_if(relations, [&](const Relation& relation) {
        return std::min(relation.t1_s, relation.t2_s) < from_s || std::max(relation.t1_s, relation.t2_s) > to_s;
      });
      sequence.relations_outside_log += before - relations.size();
    }
    sequence.relations = ShiftedRelations(std::move(relations), options.relations_rate, options.relations_offset_s);
    if (recorded) {
      // Repaired reading stamps moved: the relations follow their raw scans (the logged stamps name them).
      std::size_t unmatched = 0;
      const double tolerance_s =
          options.relations_match_tolerance_s.value_or(0.5 * MedianSpacingS(recorded->logged_stamps_s));
      sequence.relations = MapRelationsOntoReadings(std::move(*sequence.relations), *recorded, tolerance_s, unmatched);
      if (unmatched > 0) {
        sequence.warnings.push_back(Located(
            *options.relations_path, 0,
            fmt::format(
                "{} of {} relation stamps lie farther than {} s from every recorded ODOM reading of {} and keep "
                "their own time",
                unmatched, 2 * sequence.relations->size(), tolerance_s, source.string())));
      }
    } else if (!logged_pose_is_reference) {
      // A raw log: relation stamps name its scans by their recorded stamps, and follow any re-timed scan.
      // A relation with a stamp beyond the recorded ones names no scan of this log: it is outside it.
      const auto extremes = std::minmax_element(recorded_stamps_s.begin(), recorded_stamps_s.end());
      const auto low = extremes.first;
      const auto high = extremes.second;
      const std::size_t before = sequence.relations->size();
      std::erase_if(*sequence.relations, [&](const Relation& relation) {
        return std::min(relation.t1_s, relation.t2_s) < *low || std::max(relation.t1_s, relation.t2_s) > *high;
      });
      sequence.relations_outside_log += before - sequence.relations->size();
      std::size_t unmatched = 0;
      const double tolerance_s = options.relations_match_tolerance_s.value_or(0.5 * MedianSpacingS(recorded_stamps_s));
      sequence.relations =
          MapRelationsOntoRecords(std::move(*sequence.relations), recorded_stamps_s, stamps_s, tolerance_s, unmatched);
      if (unmatched > 0) {
        sequence.warnings.push_back(Located(
            *options.relations_path, 0,
            fmt::format("{} of {} relation stamps lie farther than {:.3f} s from every scan of {} and keep their own "
                        "time",
                        unmatched, 2 * sequence.relations->size(), tolerance_s, source.string())));
      }
    }
  }
  if (recorded) {
    sequence.odometry_readings = std::move(recorded->readings);
  } else if (!logged_pose_is_reference && log.odometry.size() > records.size()) {
    sequence.odometry_readings = RawLogReadings(log);
    if (sequence.odometry_readings.empty() || !ReadingsHoldScanStamps(sequence.odometry_readings, stamps_s)) {
      sequence.odometry_readings = Trajectory();
      sequence.warnings.push_back(
          Located(source, 0,
                  fmt::format("{} ODOM records not used: their stamps do not increase through the scans' stamps; the "
                              "odometry is the laser records' own, one pose per scan",
                              log.odometry.size())));
    }
  }
  KeepRelationsInsideLog(sequence);
  sequence.provenance = ProvenanceOf(source, options);
  return sequence;
}

Sequence ReadCarmenSequence(const std::filesystem::path& path, const CarmenSequenceOptions& options) {
  CheckCarmenSequenceOptions(options);
  return CarmenLogToSequence(ReadCarmenLog(path), path, options);
}

}  // namespace slamsweep::evaluator::inline sequence
