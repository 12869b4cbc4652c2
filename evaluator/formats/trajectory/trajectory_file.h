#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "evaluator/core/trajectory.h"
#include "evaluator/formats/trajectory/carmen_format.h"
#include "evaluator/formats/trajectory/mrpt_path_format.h"
#include "evaluator/formats/trajectory/trajectory_format.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {

struct TrajectoryReadOptions {
  /// KITTI: the times file (one stamp per pose line). Empty: stamps are the pose index (0, 1, 2 ... s).
  std::filesystem::path kitti_times_path;
  /// MRPT path: stamps of the rawlog steps (step i -> mrpt_step_stamps_s[i]). Empty: the file's
  /// own timestamps (rbpf-slam) or the step index as seconds (icp-slam).
  std::vector<double> mrpt_step_stamps_s;
  /// CARMEN: how far the log's clock is trusted.
  CarmenReadOptions carmen;
};

/// A trajectory file as read: the poses, the format it was read as, and notes for the user
/// (CARMEN clock problems) that the caller may print; the evaluator itself never logs.
struct TrajectoryFile {
  Trajectory trajectory;
  TrajectoryFormat format = TrajectoryFormat::kAuto;
  std::vector<std::string> warnings;
};

/// Reads `path` (plain or gzip) as `format`, detecting it with DetectTrajectoryFormat when kAuto.
/// Every failure is an InputError naming the file (and line, field or option); so is an option
/// for another format than the one read (kitti_times_path on a TUM file), which would otherwise
/// be silently ignored.
TrajectoryFile ReadTrajectoryFile(const std::filesystem::path& path, TrajectoryFormat format = TrajectoryFormat::kAuto,
                                  const TrajectoryReadOptions& options = {});
/// ReadTrajectoryFile without the notes.
Trajectory ReadTrajectory(const std::filesystem::path& path, TrajectoryFormat format = TrajectoryFormat::kAuto,
                          const TrajectoryReadOptions& options = {});

struct TrajectoryWriteOptions {
  /// KITTI: where to write the stamps (KITTI's times.txt). Empty: the stamps are not written.
  std::filesystem::path kitti_times_path;
  /// MRPT path: rbpf-slam's layout keeps stamps and 3D poses; icp-slam's keeps neither.
  MrptPathLayout mrpt_layout = MrptPathLayout::kRbpfSlam;
};

/// Writes `trajectory` to `path` in `format` (kAuto: from the file name, see FormatForOutputPath),
/// in full double precision. Planar-only formats (CARMEN, MRPT icp-slam) reject 3D poses.
void WriteTrajectory(const Trajectory& trajectory, const std::filesystem::path& path,
                     TrajectoryFormat format = TrajectoryFormat::kAuto, const TrajectoryWriteOptions& options = {});

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
