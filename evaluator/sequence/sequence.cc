#include "evaluator/sequence/sequence.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "evaluator/core/input_error.h"
#include "evaluator/sequence/robot_log.h"  // RobotLog shares the sequence invariant, checked here

namespace slamsweep::evaluator::inline sequence {
namespace {

[[noreturn]] void Fail(const std::string& name, const std::string& message) {
  throw InputError("sequence '" + name + "': " + message);
}

void CheckScan(const std::string& name, const LaserScan& scan, std::size_t index) {
  const std::string where = "scan " + std::to_string(index) + ": ";
  if (scan.ranges_m.empty()) Fail(name, where + "has no beams");
  if (!std::isfinite(scan.stamp_s)) Fail(name, where + "timestamp is not a finite number");
  if (!std::isfinite(scan.angle_min_rad) || !std::isfinite(scan.angle_increment_rad) ||
      scan.angle_increment_rad == 0.0) {
    Fail(name, where + "expected a finite start angle and a finite non-zero angle increment");
  }
  if (!(scan.range_min_m >= 0.0) || !(scan.range_max_m > scan.range_min_m) || !std::isfinite(scan.range_max_m)) {
    Fail(name, where + fmt::format("expected 0 <= range_min_m < range_max_m (finite), got {} and {}", scan.range_min_m,
                                   scan.range_max_m));
  }
  if (!scan.sensor_pose_on_robot.IsValid()) Fail(name, where + "sensor pose is not a valid pose");
}

/// The invariant shared by a sequence and the robot log a program reads.
void ValidateScansAndOdometry(const std::string& name, const std::vector<LaserScan>& scans,
                              const Trajectory& odometry) {
  const std::size_t count = scans.size();
  for (std::size_t i = 0; i < count; ++i) {
    CheckScan(name, scans[i], i);
    if (i > 0 && !(scans[i].stamp_s > scans[i - 1].stamp_s)) {
      Fail(name, fmt::format("scan {}: stamp {} s does not come after the previous scan's {} s", i, scans[i].stamp_s,
                             scans[i - 1].stamp_s));
    }
  }
  if (odometry.size() != count) {
    Fail(name,
         "expected one odometry pose per scan (" + std::to_string(count) + "), got " + std::to_string(odometry.size()));
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (odometry.stamps_s()[i] != scans[i].stamp_s) {
      Fail(name,
           fmt::format("odometry pose {} has stamp {} s, its scan {} s", i, odometry.stamps_s()[i], scans[i].stamp_s));
    }
  }
}

void ValidateReadings(const std::string& name, const Trajectory& readings) {
  const std::vector<double>& stamps = readings.stamps_s();
  for (std::size_t i = 1; i < stamps.size(); ++i) {
    if (!(stamps[i] > stamps[i - 1])) {
      Fail(name, fmt::format("odometry reading {}: stamp {} s does not come after the previous reading's {} s", i,
                             stamps[i], stamps[i - 1]));
    }
  }
}

}  // namespace

void ValidateSequence(const Sequence& sequence) {
  ValidateScansAndOdometry(sequence.name, sequence.scans, sequence.odometry);
  ValidateReadings(sequence.name, sequence.odometry_readings);
}

void ValidateRobotLog(const RobotLog& log) {
  ValidateScansAndOdometry(log.name, log.scans, log.odometry);
  ValidateReadings(log.name, log.odometry_readings);
}

RobotLog RobotLogOf(const Sequence& sequence) {
  return RobotLog{sequence.name, sequence.scans, sequence.odometry, sequence.odometry_readings};
}

RobotLog TakeRobotLog(Sequence& sequence) {
  RobotLog log{sequence.name, std::move(sequence.scans), std::move(sequence.odometry),
               std::move(sequence.odometry_readings)};
  sequence.scans.clear();
  sequence.odometry = Trajectory();
  sequence.odometry_readings = Trajectory();
  return log;
}

bool OdometryEqualsReference(const Sequence& sequence) {
  constexpr double kSameM = 1e-6;
  constexpr double kSameRad = 1e-6;
  if (!sequence.reference || sequence.odometry.empty()) return false;
  const std::vector<double>& stamps = sequence.reference->stamps_s();
  std::size_t j = 0;
  for (std::size_t i = 0; i < sequence.odometry.size(); ++i) {
    const double stamp = sequence.odometry.stamps_s()[i];
    while (j < stamps.size() && stamps[j] < stamp) ++j;
    if (j == stamps.size() || stamps[j] != stamp) return false;
    const Pose& odometry = sequence.odometry.poses()[i];
    const Pose& reference = sequence.reference->poses()[j];
    if ((odometry.position - reference.position).norm() > kSameM ||
        RotationAngleRad(odometry.orientation.inverse() * reference.orientation) > kSameRad) {
      return false;
    }
  }
  return true;
}

void KeepRelationsInsideLog(Sequence& sequence) {
  if (!sequence.relations) return;
  if (sequence.scans.empty()) {
    sequence.relations_outside_log += sequence.relations->size();
    sequence.relations.reset();
    return;
  }
  double first_s = sequence.scans.front().stamp_s;
  double last_s = sequence.scans.back().stamp_s;
  if (!sequence.odometry_readings.empty()) {
    first_s = std::min(first_s, sequence.odometry_readings.stamps_s().front());
    last_s = std::max(last_s, sequence.odometry_readings.stamps_s().back());
  }
  const std::size_t before = sequence.relations->size();
  std::erase_if(*sequence.relations, [&](const Relation& relation) {
    return std::min(relation.t1_s, relation.t2_s) < first_s || std::max(relation.t1_s, relation.t2_s) > last_s;
  });
  sequence.relations_outside_log += before - sequence.relations->size();
  if (sequence.relations->empty()) sequence.relations.reset();
}

}  // namespace slamsweep::evaluator::inline sequence
