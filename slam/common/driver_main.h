#pragma once

#include <functional>
#include <memory>
#include <string_view>

#include "evaluator/sequence/robot_log.h"
#include "slam/common/driver_args.h"
#include "slam/common/driver_io.h"
#include "slam/common/parameters.h"

namespace slamsweep::slam {

/// One configured roster algorithm, ready for the scans.
class Algorithm {
 public:
  virtual ~Algorithm() = default;
  /// Feeds every scan in order: outputs.AddPose once per scan, WriteStage when StageDue, WriteFinal
  /// at the end.
  virtual void Run(const evaluator::RobotLog& robot, DriverOutputs& outputs) = 0;
};

/// Reads every parameter the algorithm accepts (upstream names, upstream defaults) and builds it.
using Configure = std::function<std::unique_ptr<Algorithm>(Parameters& parameters, const DriverArgs& args,
                                                           const evaluator::RobotLog& robot)>;

/// The main of a driver: parses the command line, reads the input, configures the algorithm,
/// refuses parameters it did not read, writes parameters.txt (every parameter with the value used)
/// and runs it. Exit codes: 0 success; 2 bad command line, input or parameter (message
/// "<program>: error: ..." naming the argument, file or line); 1 the algorithm failed.
/// `--list-parameters` prints every parameter with its default (key=value lines, as configured for
/// a 360-degree example scan) and exits: `slamsweep algorithms` shows them. Configure must therefore
/// not write files or depend on --input/--output-dir.
int DriverMain(int argc, const char* const* argv, std::string_view program, const Configure& configure);

}  // namespace slamsweep::slam
