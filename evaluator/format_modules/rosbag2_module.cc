// slamsweep-rosbag2.so: the ROS 2 bag reader and writer (our own MCAP and sqlite3 code) as a module that
// slamsweep loads only when it reads or writes a ROS 2 bag, so that SQLite, zstd and lz4 stay out of the
// programs' start (evaluator/format_modules/format_module.h says why).
#include "evaluator/formats/rosbag2/rosbag2_reader.h"
#include "evaluator/formats/rosbag2/rosbag2_writer.h"
#include "evaluator/format_modules/format_module.h"

namespace slamsweep::evaluator::inline format_modules {
namespace {

ModuleOutcome Read(const std::filesystem::path& path, const BagReadOptions& options, Sequence& sequence) {
  return RunGuarded([&] { sequence = ReadRosbag2(path, options); });
}

ModuleOutcome ReadTrajectory(const std::filesystem::path& path, const std::string& selector, Trajectory& trajectory,
                             std::vector<std::string>& warnings) {
  return RunGuarded([&] { trajectory = ReadRosbag2Trajectory(path, selector, warnings); });
}

ModuleOutcome Write(const RobotLog& log, const std::optional<Trajectory>& reference, const std::filesystem::path& path,
                    Rosbag2StorageKind storage) {
  return RunGuarded([&] { WriteRosbag2(log, reference, path, storage); });
}

ModuleOutcome Files(const std::filesystem::path& path, std::vector<std::filesystem::path>& files) {
  return RunGuarded([&] { files = Rosbag2Files(path); });
}

}  // namespace
}  // namespace slamsweep::evaluator::inline format_modules

extern "C" __attribute__((visibility("default"))) const slamsweep::evaluator::Rosbag2Module*
slamsweep_rosbag2_module() {
  static const slamsweep::evaluator::Rosbag2Module module{.read = &slamsweep::evaluator::Read,
                                                          .read_trajectory = &slamsweep::evaluator::ReadTrajectory,
                                                          .write = &slamsweep::evaluator::Write,
                                                          .files = &slamsweep::evaluator::Files};
  return &module;
}
