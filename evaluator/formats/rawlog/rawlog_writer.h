#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "evaluator/sequence/robot_log.h"

namespace slamsweep::evaluator::inline formats::inline rawlog {

/// The two layouts of an MRPT rawlog (https://www.mrpt.org/Rawlog_Format, CRawlog).
enum class RawlogForm {
  /// CActionCollection (odometry increment), CSensoryFrame (scan), ...: what icp-slam and rbpf-slam
  /// consume; MRPT's SLAM applications skip observations in the other form.
  kActionsSensoryFrames,
  /// CObservationOdometry (absolute odometry), CObservation2DRangeScan, ...: what carmen2rawlog writes.
  kObservations,
};

struct RawlogWriteOptions {
  RawlogForm form = RawlogForm::kActionsSensoryFrames;
  std::string scan_label = "LASER";
  /// kObservations only: the label of the odometry observations.
  std::string odometry_label = "ODOMETRY";
  /// gzip level, 0 (none) to 9; 1 is MRPT's own default.
  int compression_level = 1;
  /// CObservation2DRangeScan::stdError: range noise that MRPT's grid maps assume when inserting a scan.
  double range_std_m = 0.01;
};

/// Throws InputError naming the option for values out of range.
void CheckRawlogWriteOptions(const RawlogWriteOptions& options);

/// What a rawlog holds, in MRPT's terms (the numbers `rawlog-edit --info` prints).
struct RawlogSummary {
  std::size_t actions = 0;
  std::size_t sensory_frames = 0;
  /// Observations outside sensory frames.
  std::size_t observations = 0;
  std::size_t scans = 0;
  double first_stamp_s = 0.0;
  double last_stamp_s = 0.0;
};

/// Writes a robot log (scans and odometry: what a SLAM program may read) as an MRPT rawlog with libmrpt-obs's own
/// serialization (gzip-compressed, as MRPT writes them). kActionsSensoryFrames, per scan i:
///   CActionCollection{ CActionRobotMovement2D: odometry increment odometry[i-1]^-1 * odometry[i]
///     (for i = 0 the odometry pose itself, the move from the odometry origin, so that a SLAM run
///     starts in the odometry frame), Gaussian motion model with MRPT's default parameters },
///   CSensoryFrame{ CObservation2DRangeScan }.
/// kObservations, per scan: CObservationOdometry (absolute), CObservation2DRangeScan.
/// Every object carries the scan's stamp (mrpt::Clock::fromDouble). Scans: see ToMrptScan.
/// Throws InputError when the log is invalid (ValidateRobotLog), a scan has fewer than 2 beams,
/// the odometry is not planar, or the file cannot be written (a half-written file is removed).
RawlogSummary WriteRawlog(const RobotLog& log, const std::filesystem::path& path,
                          const RawlogWriteOptions& options = {});

}  // namespace slamsweep::evaluator::inline formats::inline rawlog
