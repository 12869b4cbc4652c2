#pragma once

#include <string_view>

namespace slamsweep::evaluator::inline sequence {

/// Which odometry a SLAM program gets from a log whose logged poses are a SLAM result (the
/// Radish/Freiburg "corrected" CARMEN logs).
enum class OdometryMode {
  /// The robot's own wheel odometry, rebuilt from the log's ODOM stream (RebuildRecordedOdometry):
  /// what the robot measured, drift included. A SLAM test.
  kRecorded,
  /// The odometry fields of the laser records, which in a corrected log equal the corrected pose:
  /// the program is handed the answer (an upper bound), unless noise is drawn around it.
  kReference,
};

/// "recorded", "reference".
std::string_view OdometryModeName(OdometryMode mode);
/// Inverse of OdometryModeName; InputError naming `option` and the accepted values otherwise.
OdometryMode ParseOdometryMode(std::string_view text, std::string_view option = "odometry");

}  // namespace slamsweep::evaluator::inline sequence
