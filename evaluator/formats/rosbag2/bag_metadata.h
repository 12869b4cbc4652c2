#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace slamsweep::evaluator::inline formats::inline rosbag2 {

/// One topic of a bag's metadata.yaml (topics_with_message_count).
struct Rosbag2TopicInfo {
  std::string name;
  std::string type;
  std::string serialization_format = "cdr";
  /// QoS as rosbag2 records them: a YAML text before metadata version 9 (what slamsweep writes).
  std::string offered_qos_profiles;
  std::uint64_t message_count = 0;
};

/// One split file of the bag (metadata "files", version 5 and later).
struct Rosbag2FileInfo {
  std::string path;
  std::int64_t starting_time_ns = 0;
  std::int64_t duration_ns = 0;
  std::uint64_t message_count = 0;
};

/// A bag folder's metadata.yaml (rosbag2_bagfile_information), versions 1 to 9. Fields later versions
/// added are empty in earlier ones.
struct Rosbag2Metadata {
  int version = 0;
  /// "sqlite3" or "mcap".
  std::string storage_identifier;
  /// The split files, relative to the folder, in recording order.
  std::vector<std::string> relative_file_paths;
  std::vector<Rosbag2FileInfo> files;
  std::int64_t starting_time_ns = 0;
  std::int64_t duration_ns = 0;
  std::uint64_t message_count = 0;
  std::vector<Rosbag2TopicInfo> topics;
  /// "" or "zstd" (rosbag2's compression plugin).
  std::string compression_format;
  /// "", "NONE", "FILE" (each split file compressed whole) or "MESSAGE" (each message's data).
  std::string compression_mode;
  std::string ros_distro;
};

/// Parses metadata.yaml's text. Throws InputError "`source`:LINE: ..." naming the field for YAML
/// errors, a missing rosbag2_bagfile_information, version, storage_identifier or relative_file_paths,
/// a version outside 1..9, or a field of the wrong kind.
Rosbag2Metadata ParseRosbag2Metadata(std::string_view yaml, const std::filesystem::path& source);

/// metadata.yaml's text for `metadata`, in the layout of its `version` (5: ROS 2 Humble's).
std::string FormatRosbag2Metadata(const Rosbag2Metadata& metadata);

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
