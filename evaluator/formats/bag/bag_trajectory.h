#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "evaluator/core/trajectory.h"
#include "evaluator/formats/bag/bag_topics.h"

namespace slamsweep::evaluator::inline formats::inline bag {

/// A trajectory argument that names something inside a bag, evo's way: "BAG:TOPIC" or
/// "BAG:/tf:PARENT.CHILD".
struct BagTrajectoryArgument {
  std::filesystem::path bag;
  /// "TOPIC" or "/tf:PARENT.CHILD" (empty when the argument names the bag alone).
  std::string selector;
};

/// Splits `text` into the bag and what it names: an existing file or folder named by the whole text
/// wins; otherwise the longest prefix before a ':' that exists is the bag (so "run.mcap:/tf:map.base"
/// splits after "run.mcap"). nullopt when no prefix exists.
std::optional<BagTrajectoryArgument> SplitBagTrajectoryArgument(std::string_view text);

/// The trajectory `selector` names in a bag:
///  - a topic of nav_msgs/Odometry, geometry_msgs/PoseStamped, PoseWithCovarianceStamped or
///    TransformStamped: its poses by header.stamp (a later repeat of a stamp is dropped, with a warning);
///  - "/tf:PARENT.CHILD" (or "/tf_static:..."): the pose of CHILD in PARENT from /tf and /tf_static, at
///    every stamp of the time-varying transforms between them. Frame names may hold dots: the split
///    is the one whose two frames are in the bag's tf tree.
/// Poses are projected onto the plane (x, y, yaw). Warnings are appended to `warnings`. Throws
/// InputError naming the bag, the topic or the frames (and the candidates) when the selector is empty,
/// the topic is missing or of another type, the frames are not in the tree or not joined, or nothing is
/// left.
Trajectory ReadBagTrajectory(const std::filesystem::path& bag, const BagSummary& summary, const BagMessageSource& read,
                             std::string_view selector, std::vector<std::string>& warnings);

}  // namespace slamsweep::evaluator::inline formats::inline bag
