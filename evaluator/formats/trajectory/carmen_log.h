#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "evaluator/core/pose.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {

/// Beam layout stated by a ROBOTLASER1 record. FLASER records carry none: CARMEN's old-style
/// front laser is a 180 degree fan (-90..+90 deg, counter-clockwise) with the beam count of the record.
struct CarmenBeamGeometry {
  int laser_type = 0;
  double start_angle_rad = 0.0;
  double fov_rad = 0.0;
  double angular_resolution_rad = 0.0;
  double max_range_m = 0.0;
  double accuracy_m = 0.0;
  int remission_mode = 0;
};

/// One laser scan with the poses logged beside it.
///   FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_timestamp ipc_hostname logger_timestamp
///   RLASER: the same layout, for the rear laser
///   ROBOTLASER1 laser_type start_angle fov angular_res max_range accuracy remission_mode
///       num_readings [ranges] num_remissions [remissions] laser_pose_x laser_pose_y laser_pose_theta
///       robot_pose_x robot_pose_y robot_pose_theta tv rv forward_safety side_safety turn_axis
///       ipc_timestamp ipc_hostname logger_timestamp
struct CarmenLaserRecord {
  /// "FLASER", "RLASER" or "ROBOTLASER1".
  std::string type;
  std::vector<double> ranges_m;
  /// Planar. FLASER/RLASER: x y theta (in the Radish "corrected" logs, the SLAM-corrected pose);
  /// ROBOTLASER1: robot_pose_x/y/theta.
  Pose robot_pose;
  /// Planar. FLASER/RLASER: odom_x/y/theta; ROBOTLASER1: the robot pose again (the record holds no other).
  Pose odom_pose;
  /// Planar world pose of the laser. FLASER/RLASER: x y theta (CARMEN logs the laser's pose there);
  /// ROBOTLASER1: laser_pose_x/y/theta.
  Pose laser_pose;
  /// ROBOTLASER1 only.
  std::optional<CarmenBeamGeometry> geometry;
  std::vector<double> remissions;
  double ipc_stamp_s = 0.0;
  std::string ipc_host;
  double logger_stamp_s = 0.0;
  /// Line in the log (from 1), for messages about this scan.
  std::size_t line = 0;
};

/// `ODOM x y theta tv rv accel ipc_timestamp ipc_hostname logger_timestamp`.
struct CarmenOdomRecord {
  Pose pose;
  double tv_mps = 0.0;
  double rv_radps = 0.0;
  double accel_mps2 = 0.0;
  double ipc_stamp_s = 0.0;
  std::string ipc_host;
  double logger_stamp_s = 0.0;
  std::size_t line = 0;
};

/// `PARAM name value [ipc_timestamp ipc_hostname logger_timestamp]`.
struct CarmenParam {
  std::string name;
  std::string value;
  std::size_t line = 0;
};

/// The messages of a CARMEN log that slamsweep uses, each list in file order.
struct CarmenLog {
  /// FLASER, RLASER and ROBOTLASER1 records, interleaved as in the file.
  std::vector<CarmenLaserRecord> lasers;
  std::vector<CarmenOdomRecord> odometry;
  std::vector<CarmenParam> params;
  /// How many records of every other message (NEFF, RAWLASER1, TRUEPOS, ...) were skipped.
  std::map<std::string, std::size_t> skipped_messages;
};

/// Parses the text of a CARMEN log (see ReadTextFile for gzip). `#` lines are comments;
/// unknown messages are counted and skipped. A FLASER/RLASER/ROBOTLASER1/ODOM/PARAM record with a
/// wrong field count (for lasers: the count implied by its beam and remission counts), a
/// non-numeric or non-finite number is an InputError "FILE:LINE: ..." saying what was expected.
CarmenLog ParseCarmenLog(std::string_view content, const std::filesystem::path& source);
CarmenLog ReadCarmenLog(const std::filesystem::path& path);

/// One log line (no newline) that ParseCarmenLog reads back to the same record, numbers in
/// full precision. Poses are written as x y theta (yaw of the pose). An empty host is written as "nohost".
std::string FormatCarmenRecord(const CarmenLaserRecord& record);
std::string FormatCarmenRecord(const CarmenOdomRecord& record);
std::string FormatCarmenRecord(const CarmenParam& param);

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
