#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline sequence {

/// What a robot records, and so all that a SLAM program may read: the scans (each with its
/// sensor's pose on the robot) and the odometry. It deliberately has no place for a reference
/// trajectory, relations or a reference map: every writer of program inputs (CARMEN, rawlog, TUM
/// odometry, any later format) takes this type, so a writer that leaks the answer cannot compile.
/// Invariant (ValidateRobotLog): scan stamps strictly increase and `odometry` holds one pose per
/// scan with the scan's stamp.
struct RobotLog {
  std::string name;
  std::vector<LaserScan> scans;
  Trajectory odometry;
  /// Every odometry reading recorded between the scans too (Sequence::odometry_readings); may be empty.
  Trajectory odometry_readings;
};

/// The PARAM that marks a CARMEN log as a raw robot log (FormatCarmenLog writes it): its logged
/// poses are odometry. The CARMEN reader then reads no reference from it, whatever its options say.
inline constexpr std::string_view kCarmenLoggedPoseParam = "slamsweep_logged_pose";
inline constexpr std::string_view kCarmenLoggedPoseOdometry = "odometry";

/// A copy of the sequence's scans and odometry; its reference, relations and map stay behind.
RobotLog RobotLogOf(const Sequence& sequence);

/// Moves the scans and odometry out of `sequence`, which keeps its reference, relations, map,
/// provenance and warnings (the truth that scores a run, and what is known about the data).
RobotLog TakeRobotLog(Sequence& sequence);

/// As ValidateSequence, for the robot's part: throws InputError starting with the log's name.
void ValidateRobotLog(const RobotLog& log);

}  // namespace slamsweep::evaluator::inline sequence
