#pragma once
// The calls between slamsweep and its format modules: shared objects (slamsweep-rawlog.so for MRPT
// rawlogs, slamsweep-rosbag.so for ROS 1 bags, slamsweep-rosbag2.so for ROS 2 bags) that are loaded
// only when a file in their format is read or written, so that MRPT, ROS, SQLite and the libraries
// they pull in are not loaded, relocated and initialised by every slamsweep process. Both sides are built from the same
// tree by the same compiler; the version and the layout fingerprint refuse a module left from another build.
#include <cstddef>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/rawlog/rawlog_reader.h"
#include "evaluator/formats/rawlog/rawlog_writer.h"
#include "evaluator/formats/rosbag/rosbag_reader.h"
#include "evaluator/formats/rosbag2/rosbag2_writer.h"
#include "evaluator/sequence/robot_log.h"
#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline format_modules {

/// Raise when a call or a type passed below changes in a way the sizes do not show.
inline constexpr int kFormatModuleVersion = 2;

/// The sizes of every type that crosses the boundary, folded into one number.
constexpr std::size_t FormatModuleLayout() {
  std::size_t fingerprint = 0;
  for (std::size_t size :
       {sizeof(Sequence), sizeof(RobotLog), sizeof(RawlogReadOptions), sizeof(RawlogWriteOptions),
        sizeof(RawlogSummary), sizeof(BagReadOptions), sizeof(Trajectory), sizeof(std::optional<Trajectory>),
        sizeof(std::vector<std::string>), sizeof(std::string), sizeof(std::filesystem::path)}) {
    fingerprint = fingerprint * 1000003u + size;
  }
  return fingerprint;
}

/// How a call ended. No exception crosses the boundary: the module catches everything and the
/// loader throws it again (ThrowIfFailed), InputError for bad input and runtime_error otherwise,
/// with the message the reader wrote.
struct ModuleOutcome {
  enum class Kind { kOk, kInputError, kInternalError };
  Kind kind = Kind::kOk;
  std::string message;
};

/// Runs `call`, turning any exception into a ModuleOutcome (used inside the modules).
template <typename Call>
ModuleOutcome RunGuarded(Call&& call) noexcept {
  try {
    call();
    return {};
  } catch (const InputError& error) {
    return {ModuleOutcome::Kind::kInputError, error.what()};
  } catch (const std::exception& error) {
    return {ModuleOutcome::Kind::kInternalError, error.what()};
  } catch (...) {
    return {ModuleOutcome::Kind::kInternalError, "unknown exception in a format module"};
  }
}

/// What slamsweep-rawlog.so's entry point `slamsweep_rawlog_module` returns.
struct RawlogModule {
  int version = kFormatModuleVersion;
  std::size_t layout = FormatModuleLayout();
  ModuleOutcome (*read)(const std::filesystem::path& path, const RawlogReadOptions& options, Sequence& sequence);
  ModuleOutcome (*write)(const RobotLog& log, const std::filesystem::path& path, const RawlogWriteOptions& options,
                         RawlogSummary& summary);
};

/// What slamsweep-rosbag.so's entry point `slamsweep_rosbag_module` returns.
struct RosbagModule {
  int version = kFormatModuleVersion;
  std::size_t layout = FormatModuleLayout();
  ModuleOutcome (*read)(const std::filesystem::path& path, const BagReadOptions& options, Sequence& sequence);
  /// A trajectory in the bag: "TOPIC" or "/tf:PARENT.CHILD" (ReadRosbagTrajectory).
  ModuleOutcome (*read_trajectory)(const std::filesystem::path& path, const std::string& selector,
                                   Trajectory& trajectory, std::vector<std::string>& warnings);
};

/// What slamsweep-rosbag2.so's entry point `slamsweep_rosbag2_module` returns.
struct Rosbag2Module {
  int version = kFormatModuleVersion;
  std::size_t layout = FormatModuleLayout();
  ModuleOutcome (*read)(const std::filesystem::path& path, const BagReadOptions& options, Sequence& sequence);
  ModuleOutcome (*read_trajectory)(const std::filesystem::path& path, const std::string& selector,
                                   Trajectory& trajectory, std::vector<std::string>& warnings);
  ModuleOutcome (*write)(const RobotLog& log, const std::optional<Trajectory>& reference,
                         const std::filesystem::path& path, Rosbag2StorageKind storage);
  /// The bag's files, checked to exist (Rosbag2Files).
  ModuleOutcome (*files)(const std::filesystem::path& path, std::vector<std::filesystem::path>& files);
};

}  // namespace slamsweep::evaluator::inline format_modules

extern "C" {
/// The entry points the loader looks up (dlsym) in each module.
const slamsweep::evaluator::RawlogModule* slamsweep_rawlog_module();
const slamsweep::evaluator::RosbagModule* slamsweep_rosbag_module();
const slamsweep::evaluator::Rosbag2Module* slamsweep_rosbag2_module();
}
