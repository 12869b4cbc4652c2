#pragma once

#include <filesystem>

#include "evaluator/format_modules/format_module.h"

namespace slamsweep::evaluator::inline sequence_io {

/// The MRPT rawlog / ROS 1 bag / ROS 2 bag module, loaded (dlopen) on the first call and kept for the
/// rest of the process. Throws InputError located at `file` (the file being read or written) when this
/// build has no such module ("... support not built ..."), when the module is not found (naming
/// the folders searched), cannot be loaded (the loader's reason, e.g. a missing MRPT library) or
/// comes from another build.
const RawlogModule& LoadRawlogModule(const std::filesystem::path& file);
const RosbagModule& LoadRosbagModule(const std::filesystem::path& file);
const Rosbag2Module& LoadRosbag2Module(const std::filesystem::path& file);

/// Whether the module can be loaded (loads it).
bool RawlogModuleAvailable();
bool RosbagModuleAvailable();

/// Throws what a module call reported: InputError for bad input, std::runtime_error otherwise.
void ThrowIfFailed(const ModuleOutcome& outcome);

}  // namespace slamsweep::evaluator::inline sequence_io
