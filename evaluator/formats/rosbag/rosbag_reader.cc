#include "evaluator/formats/rosbag/rosbag_reader.h"

#include "evaluator/formats/bag/bag_sequence.h"
#include "evaluator/formats/bag/bag_trajectory.h"
#include "evaluator/formats/rosbag/ros1_bag_io.h"

namespace slamsweep::evaluator::inline formats::inline rosbag {

Sequence ReadRosbag(const std::filesystem::path& bag, const BagReadOptions& options) {
  BagReadOptions named = options;
  if (named.name.empty()) named.name = bag.stem().string();
  return ReadBagSequence(
      bag, ReadRos1BagSummary(bag), [&](const BagRequest& request) { return ReadRos1BagMessages(bag, request); },
      named);
}

Trajectory ReadRosbagTrajectory(const std::filesystem::path& bag, std::string_view selector,
                                std::vector<std::string>& warnings) {
  return ReadBagTrajectory(
      bag, ReadRos1BagSummary(bag), [&](const BagRequest& request) { return ReadRos1BagMessages(bag, request); },
      selector, warnings);
}

}  // namespace slamsweep::evaluator::inline formats::inline rosbag
