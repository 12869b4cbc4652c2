#pragma once

#include <filesystem>
#include <ostream>
#include <string_view>
#include <vector>

#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {

/// KITTI odometry format: one pose per line, the 12 numbers of the row-major 3x4 matrix
/// [R | t] (r11 r12 r13 tx r21 r22 r23 ty r31 r32 r33 tz), no stamps. Stamps come from a
/// separate times file as KITTI's times.txt: one number (seconds) per line, line i for pose i.
///
/// R must be a rotation to 1e-3 (files print 6 to 9 digits, so a tighter test would reject
/// real files); it is turned into a unit quaternion. `#` lines are skipped as comments.
/// Bad fields name file, line and field; an empty file is an InputError.

/// Poses stamped by their index: pose i (the i-th pose line, from 0) gets stamp i seconds.
/// This is what a times-less KITTI file can honestly offer; associate by index, not time.
Trajectory ParseKittiPoses(std::string_view content, const std::filesystem::path& source);
/// The stamps of a times file, one per line.
std::vector<double> ParseKittiTimes(std::string_view content, const std::filesystem::path& source);

/// Reads `poses_path`, stamped from `times_path` when it is not empty (else by index, as
/// ParseKittiPoses). A times file with a different count than the poses file is an InputError
/// naming both files and both counts.
Trajectory ReadKitti(const std::filesystem::path& poses_path, const std::filesystem::path& times_path = {});
/// ReadKitti with the poses file already in memory.
Trajectory ParseKitti(std::string_view poses_content, const std::filesystem::path& poses_path,
                      const std::filesystem::path& times_path = {});

/// Full double precision, so a write/read round trip is exact up to the quaternion-matrix conversion.
void WriteKittiPoses(const Trajectory& trajectory, std::ostream& out);
void WriteKittiTimes(const Trajectory& trajectory, std::ostream& out);
/// Writes the poses, and the stamps when `times_path` is not empty.
void WriteKitti(const Trajectory& trajectory, const std::filesystem::path& poses_path,
                const std::filesystem::path& times_path = {});

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
