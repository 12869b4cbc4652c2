#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

#include "evaluator/core/trajectory.h"
#include "evaluator/formats/bag/bag_options.h"
#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline formats::inline rosbag {

/// Reads a ROS 1 bag (librosbag) into a Sequence, as ReadBagSequence (evaluator/formats/bag/bag_sequence.h)
/// describes; the name defaults to the file name without ".bag". Throws InputError naming the bag when
/// it is missing or not a ROS 1 bag, and as ReadBagSequence.
Sequence ReadRosbag(const std::filesystem::path& bag, const BagReadOptions& options = {});

/// The trajectory `selector` ("TOPIC" or "/tf:PARENT.CHILD") names in a ROS 1 bag, as
/// ReadBagTrajectory (evaluator/formats/bag/bag_trajectory.h); warnings are appended to `warnings`.
Trajectory ReadRosbagTrajectory(const std::filesystem::path& bag, std::string_view selector,
                                std::vector<std::string>& warnings);

}  // namespace slamsweep::evaluator::inline formats::inline rosbag
