#include "slam/common/driver_main.h"

#include <exception>
#include <fstream>
#include <iostream>
#include <span>

#include "evaluator/core/input_error.h"

namespace slamsweep::slam {
namespace {

void WriteParametersUsed(const Parameters& parameters, const std::filesystem::path& directory) {
  std::ofstream out(directory / "parameters.txt");
  for (const auto& [key, value] : parameters.Used()) out << key << '=' << value << '\n';
  if (!out) throw evaluator::InputError(evaluator::Located(directory / "parameters.txt", 0, "cannot write"));
}

/// What --list-parameters configures against: one 360-beam scan of a 5 m circle at the origin, so
/// that an algorithm that sizes itself from the scan geometry still reports its defaults.
evaluator::RobotLog ExampleRobotLog() {
  evaluator::RobotLog robot;
  robot.name = "example";
  evaluator::LaserScan scan;
  scan.ranges_m.assign(360, 5.0f);
  scan.angle_min_rad = -3.141592653589793;
  scan.angle_increment_rad = 2.0 * 3.141592653589793 / 360.0;
  scan.range_max_m = 30.0;
  robot.scans.push_back(scan);
  robot.odometry.Add(0.0, evaluator::Pose::Planar(0.0, 0.0, 0.0));
  return robot;
}

int ListParameters(std::string_view program, const Configure& configure) {
  try {
    Parameters parameters({});
    DriverArgs args;
    configure(parameters, args, ExampleRobotLog());
    for (const auto& [key, value] : parameters.Used()) std::cout << key << '=' << value << '\n';
    return 0;
  } catch (const std::exception& error) {
    std::cerr << program << ": error: " << error.what() << "\n";
    return 1;
  }
}

}  // namespace

int DriverMain(int argc, const char* const* argv, std::string_view program, const Configure& configure) {
  const std::span<const char* const> arguments(argv + 1, static_cast<std::size_t>(argc > 0 ? argc - 1 : 0));
  for (const char* argument : arguments) {
    if (std::string_view(argument) == "--help") {
      std::cout << DriverUsage(program);
      return 0;
    }
    if (std::string_view(argument) == "--list-parameters") return ListParameters(program, configure);
  }
  std::unique_ptr<Algorithm> algorithm;
  evaluator::RobotLog robot;
  DriverArgs args;
  try {
    args = ParseDriverArgs(arguments);
    robot = ReadDriverInput(args.input);
    Parameters parameters(args.parameters);
    algorithm = configure(parameters, args, robot);
    parameters.RejectUnread(program);
    std::filesystem::create_directories(args.output_dir);
    WriteParametersUsed(parameters, args.output_dir);
  } catch (const std::exception& error) {
    std::cerr << program << ": error: " << error.what() << "\n" << DriverUsage(program);
    return 2;
  }
  try {
    DriverOutputs outputs(args.output_dir, robot.scans.size(), args.stages);
    algorithm->Run(robot, outputs);
    return 0;
  } catch (const std::exception& error) {
    std::cerr << program << ": error: " << error.what() << "\n";
    return 1;
  }
}

}  // namespace slamsweep::slam
