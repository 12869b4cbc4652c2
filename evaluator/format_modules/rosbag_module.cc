// slamsweep-rosbag.so: the ROS 1 bag reader as a module that slamsweep loads only when it reads a
// ROS 1 bag (evaluator/format_modules/format_module.h says why).
#include "evaluator/formats/rosbag/rosbag_reader.h"
#include "evaluator/format_modules/format_module.h"

namespace slamsweep::evaluator::inline format_modules {
namespace {

ModuleOutcome Read(const std::filesystem::path& path, const BagReadOptions& options, Sequence& sequence) {
  return RunGuarded([&] { sequence = ReadRosbag(path, options); });
}

ModuleOutcome ReadTrajectory(const std::filesystem::path& path, const std::string& selector, Trajectory& trajectory,
                             std::vector<std::string>& warnings) {
  return RunGuarded([&] { trajectory = ReadRosbagTrajectory(path, selector, warnings); });
}

}  // namespace
}  // namespace slamsweep::evaluator::inline format_modules

extern "C" __attribute__((visibility("default"))) const slamsweep::evaluator::RosbagModule* slamsweep_rosbag_module() {
  static const slamsweep::evaluator::RosbagModule module{.read = &slamsweep::evaluator::Read,
                                                         .read_trajectory = &slamsweep::evaluator::ReadTrajectory};
  return &module;
}
