#include "evaluator/sequence_io/bag_trajectory_file.h"

#include <fmt/format.h>

#include <optional>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/bag/bag_trajectory.h"
#include "evaluator/sequence_io/format_modules.h"
#include "evaluator/sequence_io/sequence_file.h"

namespace slamsweep::evaluator::inline sequence_io {
namespace {

/// The bag's format, when the path is a bag.
std::optional<SequenceFormat> BagFormatOf(const std::filesystem::path& path) {
  try {
    const SequenceFormat format = DetectSequenceFormat(path);
    if (format == SequenceFormat::kRosbag || format == SequenceFormat::kRosbag2) return format;
  } catch (const InputError&) {
  }
  return std::nullopt;
}

}  // namespace

bool NamesBagTrajectory(std::string_view argument) {
  const std::optional<BagTrajectoryArgument> split = SplitBagTrajectoryArgument(argument);
  return split && BagFormatOf(split->bag).has_value();
}

Trajectory ReadBagTrajectoryArgument(std::string_view argument, std::vector<std::string>& warnings) {
  const std::optional<BagTrajectoryArgument> split = SplitBagTrajectoryArgument(argument);
  if (!split) {
    throw InputError(
        fmt::format("{}: no such file, and no bag before a ':' in it (expected BAG:TOPIC or "
                    "BAG:/tf:PARENT.CHILD)",
                    argument));
  }
  const std::optional<SequenceFormat> format = BagFormatOf(split->bag);
  if (!format) {
    throw InputError(
        fmt::format("{}: {} is not a ROS 1 or ROS 2 bag (a .bag file, a rosbag2 folder, a .db3 or "
                    ".mcap file)",
                    argument, split->bag.string()));
  }
  Trajectory trajectory;
  if (*format == SequenceFormat::kRosbag2) {
    ThrowIfFailed(LoadRosbag2Module(split->bag).read_trajectory(split->bag, split->selector, trajectory, warnings));
  } else {
    ThrowIfFailed(LoadRosbagModule(split->bag).read_trajectory(split->bag, split->selector, trajectory, warnings));
  }
  return trajectory;
}

}  // namespace slamsweep::evaluator::inline sequence_io
