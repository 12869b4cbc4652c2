#pragma once

#include <cstddef>
#include <filesystem>
#include <ostream>
#include <span>
#include <string_view>
#include <vector>

#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {

/// The two layouts of `log_estimated_path.txt` written by MRPT's SLAM apps (mrpt 2.x,
/// libs/apps/src/ICP_SLAM_App.cpp and RBPF_SLAM_App.cpp): one line per processed rawlog
/// step, no header. `step` counts the app's loop iterations from 0; it is NOT a time.
enum class MrptPathLayout {
  /// icp-slam: `step x y phi` (printf "%i %f %f %f"): planar pose, no timestamp.
  kIcpSlam,
  /// rbpf-slam: `step x y z yaw pitch roll timestamp` (printf "%u %f %f %f %f %f %f %f"): the
  /// particle-mean pose, R = Rz(yaw) Ry(pitch) Rx(roll), and the time of the step's first
  /// observation in UNIX seconds (mrpt::Clock::toDouble).
  kRbpfSlam,
};

/// A parsed path file, exactly what it holds.
struct MrptPath {
  MrptPathLayout layout = MrptPathLayout::kIcpSlam;
  std::vector<std::size_t> steps;
  std::vector<Pose> poses;
  /// One per pose for kRbpfSlam; empty for kIcpSlam.
  std::vector<double> stamps_s;
  /// Line of each pose in the file, for error messages about a step.
  std::vector<std::size_t> lines;
};

/// The layout is taken from the first data line (4 or 8 fields); every line must have it.
/// `#` and `%` lines are comments. Bad input (missing or extra fields, a negative or
/// non-integer step, non-numeric values, an empty file) is an InputError naming file and line.
MrptPath ParseMrptPath(std::string_view content, const std::filesystem::path& source);
MrptPath ReadMrptPath(const std::filesystem::path& path);

/// Stamps each pose with `step_stamps_s[step]`: the way to time an icp-slam path, given the
/// stamps of the rawlog entries the app processed, in order. Mind what a step is: one
/// action/observation pair in an "actions-SF" rawlog, but every single observation (odometry
/// included) in an observation-only rawlog.
/// A step without a stamp is an InputError naming the file, line, step and count of stamps.
Trajectory ReadMrptPath(const std::filesystem::path& path, std::span<const double> step_stamps_s);
Trajectory StampMrptPath(const MrptPath& path, std::span<const double> step_stamps_s,
                         const std::filesystem::path& source);

/// The path as a trajectory with the stamps the file holds: rbpf-slam's timestamps, or for
/// icp-slam the step index as seconds (step 7 -> 7 s), which keeps the order but is no clock.
Trajectory MrptPathTrajectory(const MrptPath& path);

/// Writes step = pose index with full double precision. kRbpfSlam keeps the stamps and any 3D
/// pose; kIcpSlam drops the stamps and requires planar poses (else InputError naming the pose).
void WriteMrptPath(const Trajectory& trajectory, std::ostream& out, MrptPathLayout layout = MrptPathLayout::kRbpfSlam);
void WriteMrptPath(const Trajectory& trajectory, const std::filesystem::path& path,
                   MrptPathLayout layout = MrptPathLayout::kRbpfSlam);

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
