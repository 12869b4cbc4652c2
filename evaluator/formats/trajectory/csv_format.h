#pragma once

#include <filesystem>
#include <ostream>
#include <string_view>

#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {

/// Comma-separated trajectories with a required header line naming the columns, in any order:
///   SE(2): timestamp,x,y,theta              (theta in radians, about +z)
///   SE(3): timestamp,x,y,z,qx,qy,qz,qw
/// Names are matched without regard to case or surrounding blanks. A missing, repeated or
/// unknown column (a typo must not silently drop data) is an InputError naming the header
/// line; so is a row with another field count than the header, or a bad number (file, line,
/// column name). `#` lines are comments; the header is the first other line.
Trajectory ParseCsv(std::string_view content, const std::filesystem::path& source);
Trajectory ReadCsv(const std::filesystem::path& path);

/// The SE(2) form when every pose is exactly planar (z, qx, qy all 0, as Pose::Planar makes
/// them), so nothing is lost; otherwise the SE(3) form. Full double precision.
void WriteCsv(const Trajectory& trajectory, std::ostream& out);
void WriteCsv(const Trajectory& trajectory, const std::filesystem::path& path);

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
