#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

namespace slamsweep::evaluator::inline formats::inline trajectory {

enum class TrajectoryFormat { kAuto, kTum, kKitti, kMrptPath, kCarmen, kCsv };

/// "auto", "tum", "kitti", "mrpt", "carmen", "csv": the names used in options and messages.
std::string_view TrajectoryFormatName(TrajectoryFormat format);
/// The inverse of TrajectoryFormatName (case-insensitive); nothing for an unknown name.
std::optional<TrajectoryFormat> ParseTrajectoryFormat(std::string_view name);

/// The format of a trajectory file, decided first by its name, then by its first data line
/// (the first line that is not blank and not a `#` or `%` comment) in `content`:
///   name log_estimated_path.txt                                   -> MRPT path
///   extension .csv, or a comma in the line                        -> CSV
///   extension .log .clf (also with .gz), or a line starting
///   with a CARMEN message (FLASER, ROBOTLASER1, ODOM, PARAM, ...)  -> CARMEN
///   extension .kitti, or 12 fields                                -> KITTI
///   extension .tum, or 8 fields ending in a unit quaternion (1e-2)  -> TUM
///   4 fields, or 8 fields starting with an integer step and not
///   ending in a unit quaternion (rbpf-slam's layout)              -> MRPT path
/// Anything else is an InputError naming the file, what its first line holds, and every format
/// tried with what it expects.
TrajectoryFormat DetectTrajectoryFormat(const std::filesystem::path& path, std::string_view content);

/// The format for writing `path`, from its name alone (.tum/.txt -> TUM, .csv, .kitti,
/// .log/.clf -> CARMEN, log_estimated_path.txt -> MRPT); InputError when the name says nothing
/// or ends in .gz (the writers produce plain text).
TrajectoryFormat FormatForOutputPath(const std::filesystem::path& path);

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
