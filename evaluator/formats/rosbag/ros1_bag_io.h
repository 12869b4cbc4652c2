#pragma once

// The boundary to librosbag. ROS 1's generated message headers use std::allocator<void>::rebind,
// which C++20 removed, so the one file that includes them (ros1_bag_io.cc) is compiled as C++17 and
// speaks only in the plain types of evaluator/formats/bag/bag_messages.h.

#include <filesystem>

#include "evaluator/formats/bag/bag_messages.h"

// Spelled the C++17 way: the ROS 1 message library, which is C++17, includes this header.
namespace slamsweep::evaluator {
inline namespace formats {
inline namespace rosbag {

/// The topics of a ROS 1 bag. Throws InputError naming the bag when it is missing or not a ROS 1 bag.
BagSummary ReadRos1BagSummary(const std::filesystem::path& bag);

/// Deserialises the requested topics. Throws InputError naming the bag (and topic) when the bag is
/// missing or unreadable, a requested topic is absent or its definition is not the one of the type it
/// claims (ROS's md5 check), or a message cannot be decoded. The caller checks each topic's type
/// against its role (evaluator/formats/bag/bag_topics.h).
BagMessages ReadRos1BagMessages(const std::filesystem::path& bag, const BagRequest& request);

}  // namespace rosbag
}  // namespace formats
}  // namespace slamsweep::evaluator
