#pragma once

#include <cstddef>
#include <filesystem>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/core/pose.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/sequence/robot_log.h"

namespace slamsweep::slam {

/// Reads a driver's --input (CARMEN log or rawlog) as what a robot has: the scans with their own
/// geometry (angles, max range, sensor pose on the robot) and the odometry. Whatever else the file
/// may hold is dropped here, so no algorithm can see it. InputError naming the file when it is
/// unreadable, malformed or holds no scan.
evaluator::RobotLog ReadDriverInput(const std::filesystem::path& input);

/// What a driver writes into --output-dir: trajectory.tum (one pose per scan, on the input's clock),
/// map.yaml + map.png (map_server scale mode, grey levels kept) and stages/stage-NNNNNN.yaml + .pgm
/// (map_server trinary, NNNNNN = scan index). The trajectory is rewritten at every stage, so a run
/// stopped by a timeout still leaves the poses it had.
class DriverOutputs {
 public:
  /// Creates `directory` and its stages/ folder. `stage_count` stage maps are spread evenly over
  /// `scan_count` scans, the last at the last scan.
  DriverOutputs(std::filesystem::path directory, std::size_t scan_count, int stage_count);

  /// The algorithm's pose estimate after scan `scan_index` (in order, one per scan).
  void AddPose(std::size_t scan_index, double stamp_s, const evaluator::Pose& pose);
  /// Replaces the poses given so far by a smoothed estimate (a particle filter's best trajectory, a
  /// pose graph after its final optimisation): one pose per scan added, same stamps.
  void ReplaceTrajectory(evaluator::Trajectory trajectory);
  /// Whether a stage map is wanted after scan `scan_index`.
  bool StageDue(std::size_t scan_index) const;
  void WriteStage(std::size_t scan_index, const evaluator::OccupancyGrid& map);
  /// The final map, and the trajectory once more.
  void WriteFinal(const evaluator::OccupancyGrid& map);

 private:
  void WriteTrajectory() const;

  std::filesystem::path directory_;
  std::size_t scan_count_;
  int stage_count_;
  evaluator::Trajectory trajectory_;
};

}  // namespace slamsweep::slam
