#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/sequence/robot_log.h"
#include "orchestrator/adapters/run_paths.h"
#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline adapters {

/// What to start for a run. The worker runs it with the run folder as working directory and
/// stdin from /dev/null; never through a shell.
struct PreparedRun {
  /// Program and arguments; empty when the adapter runs no program (the odometry baseline).
  std::vector<std::string> argv;
};

/// A run's outputs converted to evaluator types.
struct CollectedOutputs {
  /// The program's final map, or the map rendered from the trajectory when it writes none.
  evaluator::OccupancyGrid map;
  bool map_rendered_from_trajectory = false;
  /// Stamps on the sequence clock; absent when the program writes only a map.
  std::optional<evaluator::Trajectory> trajectory;
  /// Stage maps in build order as 8-bit trinary images (StageImage): 0 occupied, 254 free, 205 unknown.
  std::vector<cv::Mat> stages;
  /// Notes for result.json (scans outside the trajectory, no stage maps...).
  std::vector<std::string> warnings;
};

/// How one kind of SLAM program is run (ninja's CommandRunner split: the worker decides when,
/// the adapter knows how). Implementations are stateless and const. An adapter sees only the
/// RobotLog (scans and odometry): the reference and relations never reach it, so nothing it writes
/// for the program can hold them.
class Adapter {
 public:
  virtual ~Adapter() = default;

  /// Writes what the program reads under paths.InputDir(), creates paths.RawDir() and returns the
  /// argv. Bad parameters or declarations are InputErrors naming the field.
  virtual PreparedRun Prepare(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const = 0;

  /// Reads the program's outputs after it exited normally. A missing file is a RunFailure
  /// kMissingOutput naming it (relative to the run folder), an unreadable one kCorruptOutput
  /// naming it with the reader's message.
  virtual CollectedOutputs Collect(const RunSpec& spec, const evaluator::RobotLog& robot,
                                   const RunPaths& paths) const = 0;

  /// What the program reads besides input/, its own file and the system folders: the paths its
  /// sandbox shows it read-only (orchestrator/worker/program_sandbox.h). Absolute; may not exist.
  virtual std::vector<std::filesystem::path> ProgramReads(const RunSpec& spec) const;
  // What a run depends on (program files, seeding) is program_identity.h's: planning needs it
  // without the run-time code here.
};

/// The adapter named in run.json's algorithm.adapter: "mrpt-icp-slam", "mrpt-rbpf-slam", "command",
/// "odometry" or a roster algorithm (roster.h). Anything else is an InputError listing these.
std::unique_ptr<Adapter> MakeAdapter(std::string_view name);

}  // namespace slamsweep::orchestrator::inline adapters
