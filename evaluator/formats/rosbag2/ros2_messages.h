#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "evaluator/formats/bag/bag_messages.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {

/// The ROS 2 messages the readers understand, decoded from CDR (either byte order; see CdrReader).
/// `record_s` is the time the bag recorded the message; `where` names the message in errors
/// ("bag.mcap: topic '/scan' message 12"). Decoders throw InputError naming `where` for a truncated or
/// malformed message. Fields after the ones read (an Odometry's twist, a scan's intensities) are not
/// checked.
BagScan DecodeLaserScan(std::span<const std::uint8_t> cdr, double record_s, const std::string& where);
/// An Odometry, PoseStamped, PoseWithCovarianceStamped or TransformStamped (`kind`).
BagStampedPose DecodeStampedPose(BagMessageKind kind, std::span<const std::uint8_t> cdr, double record_s,
                                 const std::string& where);
/// A tf2_msgs/TFMessage: each of its transforms, appended to `out`.
void DecodeTfMessage(std::span<const std::uint8_t> cdr, double record_s, const std::string& where,
                     std::vector<BagStampedPose>& out);

/// Little-endian CDR of the messages slamsweep writes. Throws InputError for a stamp that is no ROS time.
std::vector<std::uint8_t> EncodeLaserScan(const BagScan& scan);
std::vector<std::uint8_t> EncodeOdometry(const BagStampedPose& odometry);
std::vector<std::uint8_t> EncodeTfMessage(const std::vector<BagStampedPose>& transforms);

/// The message definition of a type as rosbag2 embeds it (encoding "ros2msg"): the type's fields,
/// then each type it uses after a line of 80 '=' and "MSG: pkg/Type". For the types slamsweep writes
/// (LaserScan, Odometry, TFMessage); "" for others.
std::string Ros2MessageDefinition(BagMessageKind kind);

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
