#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline sequence_io {

/// Whether `argument` names a trajectory inside a ROS 1 or ROS 2 bag, evo's way ("BAG:TOPIC" or
/// "BAG:/tf:PARENT.CHILD"), or a bag alone: no file of the whole name other than a bag, and the
/// bag (the longest prefix before a ':' that exists) is a ROS 1 bag or a ROS 2 bag folder or file.
bool NamesBagTrajectory(std::string_view argument);

/// The trajectory `argument` names in a bag (ReadBagTrajectory, evaluator/formats/bag/bag_trajectory.h);
/// ROS 1 bags through their format module. Warnings are appended to `warnings`. Throws InputError
/// naming the argument when no bag is found in it, and as the bag's reader.
Trajectory ReadBagTrajectoryArgument(std::string_view argument, std::vector<std::string>& warnings);

}  // namespace slamsweep::evaluator::inline sequence_io
