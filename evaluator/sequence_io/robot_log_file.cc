#include "evaluator/sequence_io/robot_log_file.h"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/trajectory/carmen_log.h"
#include "evaluator/formats/trajectory/output_file.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "evaluator/sequence/flaser_fan.h"
#include "evaluator/sequence_io/format_modules.h"

namespace slamsweep::evaluator::inline sequence_io {
namespace {

/// Beam geometry closer than this to CARMEN's inferred fan is that fan (the fans are computed in double).
constexpr double kFanToleranceRad = 1e-9;
constexpr double kMountToleranceM = 1e-9;

/// The fan's angle, also when stored as float32 (a ROS LaserScan's angles): the float nearest to it.
bool IsFanAngle(double fan_rad, double scan_rad) {
  return std::abs(fan_rad - scan_rad) < kFanToleranceRad || static_cast<float>(fan_rad) == scan_rad;
}

/// The float's shortest decimal text read back as double, so that FormatCarmenRecord (which writes
/// doubles exactly) writes "1.23" for 1.23f instead of its 17-digit double expansion.
double ShortestFloatAsDouble(float value) {
  std::array<char, 32> text{};
  const auto [end, error] = std::to_chars(text.data(), text.data() + text.size(), value);
  double result = value;
  if (error == std::errc()) std::from_chars(text.data(), end, result);
  return result;
}

bool IsFlaserFan(const LaserScan& scan) {
  if (scan.BeamCount() < 2) return false;
  const BeamFan fan = FlaserBeamFan(scan.BeamCount());
  const Pose& mount = scan.sensor_pose_on_robot;
  return fan.known_layout && IsFanAngle(fan.angle_min_rad, scan.angle_min_rad) &&
         IsFanAngle(fan.angle_increment_rad, scan.angle_increment_rad) && mount.position.norm() < kMountToleranceM &&
         RotationAngleRad(mount.orientation) < kFanToleranceRad;
}

std::vector<double> RangesAsWritten(const LaserScan& scan) {
  std::vector<double> ranges;
  ranges.reserve(scan.BeamCount());
  for (float range : scan.ranges_m) ranges.push_back(ShortestFloatAsDouble(range));
  return ranges;
}

}  // namespace

std::string_view SequenceWriteFormatName(SequenceWriteFormat format) {
  switch (format) {
    case SequenceWriteFormat::kRawlog:
      return "rawlog";
    case SequenceWriteFormat::kCarmen:
      return "carmen";
    case SequenceWriteFormat::kTum:
      return "tum";
    case SequenceWriteFormat::kRosbag2:
      return "rosbag2";
  }
  return "unknown";
}

SequenceWriteFormat ParseSequenceWriteFormat(std::string_view text, std::string_view option) {
  for (SequenceWriteFormat format : {SequenceWriteFormat::kRawlog, SequenceWriteFormat::kCarmen,
                                     SequenceWriteFormat::kTum, SequenceWriteFormat::kRosbag2}) {
    if (text == SequenceWriteFormatName(format)) return format;
  }
  throw InputError(fmt::format("{}: expected rawlog, carmen, tum or rosbag2, got '{}'", option, text));
}

std::string FormatCarmenLog(const RobotLog& log) {
  ValidateRobotLog(log);
  bool flaser = true;
  for (const LaserScan& scan : log.scans) flaser = flaser && IsFlaserFan(scan);

  std::string out = "# " + log.name + ": raw robot log written by slamsweep (scans and odometry only)\n";
  out +=
      FormatCarmenRecord(CarmenParam{std::string(kCarmenLoggedPoseParam), std::string(kCarmenLoggedPoseOdometry), 0}) +
      '\n';
  const double max_range_m = log.scans.front().range_max_m;
  bool same_max_range = true;
  for (const LaserScan& scan : log.scans) same_max_range = same_max_range && scan.range_max_m == max_range_m;
  if (flaser && same_max_range) {
    out += FormatCarmenRecord(CarmenParam{"robot_front_laser_max", ShortestText(max_range_m), 0}) + '\n';
  }
  const auto odom_line = [](double stamp_s, const Pose& pose) {
    CarmenOdomRecord odom;
    odom.pose = pose;
    odom.ipc_stamp_s = stamp_s;
    odom.logger_stamp_s = stamp_s;
    return FormatCarmenRecord(odom) + '\n';
  };
  const Trajectory& readings = log.odometry_readings;
  std::size_t next_reading = 0;
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    const LaserScan& scan = log.scans[i];
    const Pose& odometry = log.odometry.poses()[i];
    // Every recorded reading up to the scan, as a raw log holds them; the scan's own odometry last.
    while (next_reading < readings.size() && readings.stamps_s()[next_reading] < scan.stamp_s) {
      out += odom_line(readings.stamps_s()[next_reading], readings.poses()[next_reading]);
      ++next_reading;
    }
    if (next_reading < readings.size() && readings.stamps_s()[next_reading] == scan.stamp_s) ++next_reading;
    out += odom_line(scan.stamp_s, odometry);

    CarmenLaserRecord laser;
    laser.ranges_m = RangesAsWritten(scan);
    laser.ipc_stamp_s = scan.stamp_s;
    laser.logger_stamp_s = scan.stamp_s;
    // A raw log's logged pose is where the odometry puts the robot: that is all a robot knows.
    laser.robot_pose = odometry;
    if (flaser) {
      laser.type = "FLASER";
      laser.odom_pose = odometry;
    } else {
      laser.type = "ROBOTLASER1";
      CarmenBeamGeometry geometry;
      geometry.start_angle_rad = scan.angle_min_rad;
      geometry.angular_resolution_rad = scan.angle_increment_rad;
      geometry.fov_rad = scan.angle_increment_rad * static_cast<double>(scan.BeamCount() - 1);
      geometry.max_range_m = scan.range_max_m;
      laser.geometry = geometry;
      laser.laser_pose = odometry * scan.sensor_pose_on_robot;
    }
    out += FormatCarmenRecord(laser) + '\n';
  }
  for (; next_reading < readings.size(); ++next_reading) {
    out += odom_line(readings.stamps_s()[next_reading], readings.poses()[next_reading]);
  }
  return out;
}

void WriteRobotLog(const RobotLog& log, const std::filesystem::path& path, SequenceWriteFormat format) {
  switch (format) {
    case SequenceWriteFormat::kRawlog: {
      RawlogSummary summary;
      ThrowIfFailed(LoadRawlogModule(path).write(log, path, RawlogWriteOptions{}, summary));
      return;
    }
    case SequenceWriteFormat::kCarmen: {
      const std::string text = FormatCarmenLog(log);
      WriteOutputFile(path, [&](std::ostream& out) { out << text; });
      return;
    }
    case SequenceWriteFormat::kTum:
      ValidateRobotLog(log);
      WriteTum(log.odometry, path);
      return;
    case SequenceWriteFormat::kRosbag2:
      // A program's input: never a reference.
      WriteRosbag2Folder(log, std::nullopt, path, Rosbag2StorageKind::kMcap);
      return;
  }
}

void WriteRosbag2Folder(const RobotLog& log, const std::optional<Trajectory>& reference,
                        const std::filesystem::path& folder, Rosbag2StorageKind storage) {
  ThrowIfFailed(LoadRosbag2Module(folder).write(log, reference, folder, storage));
}

}  // namespace slamsweep::evaluator::inline sequence_io
