#pragma once

#include <filesystem>
#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "evaluator/formats/bag/bag_messages.h"

namespace slamsweep::evaluator::inline formats::inline bag {

/// Reads the messages a request names from one bag; each bag format's reader provides it. Throws
/// InputError naming the bag (and topic or record) when the bag cannot be read or a message decoded.
using BagMessageSource = std::function<BagMessages(const BagRequest& request)>;

/// "topics in the bag: /odom (nav_msgs/msg/Odometry), ..." or "the bag has no topics".
std::string DescribeTopics(const BagSummary& summary);

/// Topics whose type is of `kind`, sorted.
std::vector<std::string> TopicsOfKind(const BagSummary& summary, BagMessageKind kind);

/// The topic named `topic`, which must hold one of `kinds`. Throws InputError
/// "`bag`: no `role` topic '...'; topics in the bag: ..." or "`bag`: `role` topic '...' holds TYPE,
/// expected A or B".
const BagTopic& RequireTopic(const std::filesystem::path& bag, const BagSummary& summary, std::string_view topic,
                             std::string_view role, std::initializer_list<BagMessageKind> kinds);

/// The kinds a pose topic (a reference, a trajectory) may hold.
inline constexpr std::initializer_list<BagMessageKind> kReferenceKinds = {
    BagMessageKind::kOdometry, BagMessageKind::kPoseStamped, BagMessageKind::kPoseWithCovarianceStamped};
inline constexpr std::initializer_list<BagMessageKind> kTrajectoryKinds = {
    BagMessageKind::kOdometry, BagMessageKind::kPoseStamped, BagMessageKind::kPoseWithCovarianceStamped,
    BagMessageKind::kTransformStamped};

}  // namespace slamsweep::evaluator::inline formats::inline bag
