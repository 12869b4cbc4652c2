#pragma once

// The trajectory targets: one reader of trajectory files (ReadTrajectoryFile) in one explicit format each.
#include <filesystem>
#include <initializer_list>

#include "evaluator/formats/trajectory/trajectory_file.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/seed_data.h"

namespace slamsweep::fuzz {

/// Reads `file` as `format`: it returns or throws InputError naming one of `files`.
inline void CheckTrajectoryRead(std::initializer_list<std::filesystem::path> files, const std::filesystem::path& file,
                                evaluator::TrajectoryFormat format,
                                const evaluator::TrajectoryReadOptions& options = {}) {
  ExpectReadOrInputError(files, [&] { evaluator::ReadTrajectoryFile(file, format, options); });
}

/// What WriteTrajectory writes for `trajectory` in `format` (a seed).
inline std::string WrittenTrajectory(const Seeds& seeds, const evaluator::Trajectory& trajectory, std::string_view name,
                                     evaluator::TrajectoryFormat format,
                                     const evaluator::TrajectoryWriteOptions& options = {}) {
  const std::filesystem::path path = seeds.folder() / name;
  evaluator::WriteTrajectory(trajectory, path, format, options);
  std::string bytes = FileBytes(path);
  std::filesystem::remove(path);
  return bytes;
}

}  // namespace slamsweep::fuzz
