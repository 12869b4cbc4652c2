#pragma once

#include <filesystem>
#include <ostream>
#include <string_view>

#include "evaluator/core/relation.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {

/// Kuemmerle et al. (2009) relations files: one relation per line,
/// `t1 t2 x y z roll pitch yaw` = the pose at t2 in the frame of the pose at t1, with
/// R = Rz(yaw) Ry(pitch) Rx(roll) (rotations about the fixed X, Y, Z axes, radians).
/// `#` lines are comments. A line with another field count, a non-numeric or non-finite
/// field, or a file without relations is an InputError naming file and line.
Relations ParseRelations(std::string_view content, const std::filesystem::path& source);
Relations ReadRelations(const std::filesystem::path& path);

/// Full double precision, so that a write/read round trip is exact up to the angle conversion.
void WriteRelations(const Relations& relations, std::ostream& out);
void WriteRelations(const Relations& relations, const std::filesystem::path& path);

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
