#include "evaluator/formats/trajectory/carmen_log.h"

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "evaluator/formats/trajectory/output_file.h"

namespace slamsweep::evaluator {
namespace {

constexpr std::string_view kFlaserLayout =
    "FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_timestamp ipc_hostname logger_timestamp";
constexpr std::string_view kRobotLaserLayout =
    "ROBOTLASER1 laser_type start_angle fov angular_res max_range accuracy remission_mode num_readings [ranges] "
    "num_remissions [remissions] laser_pose_x laser_pose_y laser_pose_theta robot_pose_x robot_pose_y "
    "robot_pose_theta tv rv forward_safety side_safety turn_axis ipc_timestamp ipc_hostname logger_timestamp";
constexpr std::string_view kOdomLayout = "ODOM x y theta tv rv accel ipc_timestamp ipc_hostname logger_timestamp";
constexpr std::string_view kParamLayout = "PARAM name value [ipc_timestamp ipc_hostname logger_timestamp]";

/// A count field (beams, remissions) that must leave room for `fields_after` more fields.
std::size_t ReadCount(const TextRecord& record, std::size_t index, std::string_view name) {
  const long long count = record.Integer(index, name);
  if (count < 0) {
    record.Fail("field " + std::to_string(index + 1) + " (" + std::string(name) + "): expected a count >= 0, got " +
                std::to_string(count));
  }
  // Larger than the line itself: no field count can match; say so before any arithmetic overflows.
  if (static_cast<unsigned long long>(count) > record.size()) {
    record.Fail("field " + std::to_string(index + 1) + " (" + std::string(name) + ") says " + std::to_string(count) +
                " values but the line has only " + std::to_string(record.size()) + " fields");
  }
  return static_cast<std::size_t>(count);
}

void RequireExactFields(const TextRecord& record, std::size_t expected, std::string_view why, std::string_view layout) {
  if (record.size() != expected) {
    record.Fail(std::string(why) + " needs " + std::to_string(expected) + " fields, got " +
                std::to_string(record.size()) +
                " (a truncated line, or a count that disagrees with its values?); layout: " + std::string(layout));
  }
}

std::vector<double> ReadNumbers(const TextRecord& record, std::size_t first, std::size_t count, std::string_view name) {
  std::vector<double> values(count);
  for (std::size_t i = 0; i < count; ++i) values[i] = record.Number(first + i, name);
  return values;
}

Pose ReadPlanarPose(const TextRecord& record, std::size_t first, std::string_view prefix) {
  const std::string p(prefix);
  return Pose::Planar(record.Number(first, p + "x"), record.Number(first + 1, p + "y"),
                      record.Number(first + 2, p + "theta"));
}

CarmenLaserRecord ParseFlaser(const TextRecord& record) {
  record.RequireFields(2, kFlaserLayout);
  const std::size_t beams = ReadCount(record, 1, "num_readings");
  RequireExactFields(record, beams + 11, "FLASER with num_readings = " + std::to_string(beams), kFlaserLayout);
  CarmenLaserRecord laser;
  laser.type = "FLASER";
  laser.ranges_m = ReadNumbers(record, 2, beams, "range");
  const std::size_t base = 2 + beams;
  laser.robot_pose = ReadPlanarPose(record, base, "");
  laser.laser_pose = laser.robot_pose;
  laser.odom_pose = ReadPlanarPose(record, base + 3, "odom_");
  laser.ipc_stamp_s = record.Number(base + 6, "ipc_timestamp");
  laser.ipc_host = std::string(record.Text(base + 7));
  laser.logger_stamp_s = record.Number(base + 8, "logger_timestamp");
  laser.line = record.line_number();
  return laser;
}

CarmenLaserRecord ParseRobotLaser(const TextRecord& record) {
  record.RequireFields(10, kRobotLaserLayout);
  CarmenLaserRecord laser;
  laser.type = "ROBOTLASER1";
  CarmenBeamGeometry geometry;
  geometry.laser_type = static_cast<int>(record.Integer(1, "laser_type"));
  geometry.start_angle_rad = record.Number(2, "start_angle");
  geometry.fov_rad = record.Number(3, "fov");
  geometry.angular_resolution_rad = record.Number(4, "angular_res");
  geometry.max_range_m = record.Number(5, "max_range");
  geometry.accuracy_m = record.Number(6, "accuracy");
  geometry.remission_mode = static_cast<int>(record.Integer(7, "remission_mode"));
  laser.geometry = geometry;
  const std::size_t beams = ReadCount(record, 8, "num_readings");
  record.RequireFields(10 + beams, kRobotLaserLayout);
  const std::size_t remissions = ReadCount(record, 9 + beams, "num_remissions");
  RequireExactFields(record, 24 + beams + remissions,
                     "ROBOTLASER1 with num_readings = " + std::to_string(beams) +
                         " and num_remissions = " + std::to_string(remissions),
                     kRobotLaserLayout);
  laser.ranges_m = ReadNumbers(record, 9, beams, "range");
  laser.remissions = ReadNumbers(record, 10 + beams, remissions, "remission");
  const std::size_t base = 10 + beams + remissions;
  laser.laser_pose = ReadPlanarPose(record, base, "laser_pose_");
  laser.robot_pose = ReadPlanarPose(record, base + 3, "robot_pose_");
  laser.odom_pose = laser.robot_pose;
  // tv rv forward_safety side_safety turn_axis: checked as numbers, not kept.
  ReadNumbers(record, base + 6, 5, "tv/rv/forward_safety/side_safety/turn_axis");
  laser.ipc_stamp_s = record.Number(base + 11, "ipc_timestamp");
  laser.ipc_host = std::string(record.Text(base + 12));
  laser.logger_stamp_s = record.Number(base + 13, "logger_timestamp");
  laser.line = record.line_number();
  return laser;
}

CarmenOdomRecord ParseOdom(const TextRecord& record) {
  RequireExactFields(record, 10, "ODOM", kOdomLayout);
  CarmenOdomRecord odom;
  odom.pose = ReadPlanarPose(record, 1, "");
  odom.tv_mps = record.Number(4, "tv");
  odom.rv_radps = record.Number(5, "rv");
  odom.accel_mps2 = record.Number(6, "accel");
  odom.ipc_stamp_s = record.Number(7, "ipc_timestamp");
  odom.ipc_host = std::string(record.Text(8));
  odom.logger_stamp_s = record.Number(9, "logger_timestamp");
  odom.line = record.line_number();
  return odom;
}

std::string Host(const std::string& host) { return host.empty() ? "nohost" : host; }

void AppendPose(std::string& out, const Pose& pose) {
  out += ' ' + ShortestText(pose.position.x()) + ' ' + ShortestText(pose.position.y()) + ' ' + ShortestText(pose.Yaw());
}

void AppendNumbers(std::string& out, const std::vector<double>& values) {
  for (double value : values) out += ' ' + ShortestText(value);
}

}  // namespace

CarmenLog ParseCarmenLog(std::string_view content, const std::filesystem::path& source) {
  CarmenLog log;
  ForEachRecord(source, content, [&](const TextRecord& record) {
    const std::string_view type = record.Text(0);
    if (type == "FLASER") {
      log.lasers.push_back(ParseFlaser(record));
    } else if (type == "ROBOTLASER1") {
      log.lasers.push_back(ParseRobotLaser(record));
    } else if (type == "ODOM") {
      log.odometry.push_back(ParseOdom(record));
    } else if (type == "PARAM") {
      record.RequireFields(3, kParamLayout);
      log.params.push_back({std::string(record.Text(1)), std::string(record.Text(2)), record.line_number()});
    } else {
      ++log.skipped_messages[std::string(type)];
    }
  });
  return log;
}

CarmenLog ReadCarmenLog(const std::filesystem::path& path) { return ParseCarmenLog(ReadTextFile(path), path); }

std::string FormatCarmenRecord(const CarmenLaserRecord& record) {
  std::string out;
  if (record.type == "ROBOTLASER1") {
    const CarmenBeamGeometry geometry = record.geometry.value_or(CarmenBeamGeometry{});
    out = "ROBOTLASER1 " + std::to_string(geometry.laser_type) + ' ' + ShortestText(geometry.start_angle_rad) + ' ' +
          ShortestText(geometry.fov_rad) + ' ' + ShortestText(geometry.angular_resolution_rad) + ' ' +
          ShortestText(geometry.max_range_m) + ' ' + ShortestText(geometry.accuracy_m) + ' ' +
          std::to_string(geometry.remission_mode) + ' ' + std::to_string(record.ranges_m.size());
    AppendNumbers(out, record.ranges_m);
    out += ' ' + std::to_string(record.remissions.size());
    AppendNumbers(out, record.remissions);
    AppendPose(out, record.laser_pose);
    AppendPose(out, record.robot_pose);
    out += " 0 0 0 0 0";  // tv rv forward_safety side_safety turn_axis: not kept by the parser
  } else {
    out = "FLASER " + std::to_string(record.ranges_m.size());
    AppendNumbers(out, record.ranges_m);
    AppendPose(out, record.robot_pose);
    AppendPose(out, record.odom_pose);
  }
  out +=
      ' ' + ShortestText(record.ipc_stamp_s) + ' ' + Host(record.ipc_host) + ' ' + ShortestText(record.logger_stamp_s);
  return out;
}

std::string FormatCarmenRecord(const CarmenOdomRecord& record) {
  std::string out = "ODOM";
  AppendPose(out, record.pose);
  out += ' ' + ShortestText(record.tv_mps) + ' ' + ShortestText(record.rv_radps) + ' ' +
         ShortestText(record.accel_mps2) + ' ' + ShortestText(record.ipc_stamp_s) + ' ' + Host(record.ipc_host) + ' ' +
         ShortestText(record.logger_stamp_s);
  return out;
}

std::string FormatCarmenRecord(const CarmenParam& param) { return "PARAM " + param.name + ' ' + param.value; }

}  // namespace slamsweep::evaluator
