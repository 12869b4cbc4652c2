#pragma once

#include <filesystem>
#include <ostream>
#include <string_view>

#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {

/// TUM RGB-D format: one pose per line, `timestamp tx ty tz qx qy qz qw`; `#` comments.
/// Quaternions are normalised on read (files carry 9 digits); a line with a quaternion
/// of zero norm, a non-numeric or missing field is an InputError naming file and line.
Trajectory ParseTum(std::string_view content, const std::filesystem::path& source);
Trajectory ReadTum(const std::filesystem::path& path);

/// Writes with full double precision, so that a write/read round trip is exact.
void WriteTum(const Trajectory& trajectory, std::ostream& out);
void WriteTum(const Trajectory& trajectory, const std::filesystem::path& path);

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
