#pragma once

// Seeds of the ROS 2 bag targets: the simulated run written by slamsweep's rosbag2 writer, and messages and
// compressed chunks cut from the real bags of ../shared/datasets/ros2 when the seeds are written.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "evaluator/formats/rosbag2/rosbag2_writer.h"
#include "tests/fuzz/fuzz_support.h"

namespace slamsweep::fuzz {

/// The real bags: an MCAP file (evo's nav2 turtlebot run) and a .db3 (evo's tf example).
inline constexpr char kSharedMcap[] = "datasets/ros2/evo-nav2-turtlebot/nav2_turtlebot.mcap";
inline constexpr char kSharedDb3[] = "datasets/ros2/evo-tf-example/tf_example.db3";

/// A bag folder written by WriteRosbag2 from the first `scans` scans of the seed run (with its ground truth
/// when `with_reference`): its metadata.yaml and its one split file.
struct SeedBag {
  std::filesystem::path folder;
  std::filesystem::path metadata;
  std::filesystem::path split_file;
};
SeedBag WriteSeedBag(const std::filesystem::path& folder, evaluator::Rosbag2StorageKind storage, std::size_t scans,
                     bool with_reference);

/// One message of a storage file, with its topic's type.
struct SeedMessage {
  std::string topic;
  std::string type;
  std::vector<std::uint8_t> data;
};

/// The first `per_topic` messages of each topic of a storage file (.mcap or .db3), read by slamsweep's reader.
std::vector<SeedMessage> FirstMessages(const std::filesystem::path& file, std::size_t per_topic);

/// A shared file's path, or nothing (listed as missing by `seeds`).
std::optional<std::filesystem::path> SharedPath(Seeds& seeds, const std::filesystem::path& relative);

}  // namespace slamsweep::fuzz
