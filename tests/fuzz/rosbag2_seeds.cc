#include "tests/fuzz/rosbag2_seeds.h"

#include <map>
#include <optional>
#include <set>

#include "evaluator/formats/rosbag2/rosbag2_storage.h"
#include "tests/fuzz/seed_data.h"

namespace slamsweep::fuzz {

SeedBag WriteSeedBag(const std::filesystem::path& folder, evaluator::Rosbag2StorageKind storage, std::size_t scans,
                     bool with_reference) {
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder.parent_path());
  const evaluator::RobotLog log = SeedLog(scans, 61, 3.0);
  std::optional<evaluator::Trajectory> reference;
  if (with_reference) reference = SeedGroundTruth(scans);
  evaluator::WriteRosbag2(log, reference, folder, storage);
  const std::string extension = storage == evaluator::Rosbag2StorageKind::kMcap ? ".mcap" : ".db3";
  return {folder, folder / "metadata.yaml", folder / (folder.filename().string() + "_0" + extension)};
}

std::vector<SeedMessage> FirstMessages(const std::filesystem::path& file, std::size_t per_topic) {
  const auto storage = evaluator::Rosbag2File::Open(file, "", false);
  std::set<std::string> topics;
  std::map<std::string, std::string> types;
  for (const evaluator::StorageTopic& topic : storage->Topics()) {
    topics.insert(topic.name);
    types[topic.name] = topic.type;
  }
  std::map<std::string, std::size_t> taken;
  std::vector<SeedMessage> messages;
  storage->ReadMessages(topics, [&](const std::string& topic, std::int64_t, std::span<const std::uint8_t> data) {
    if (taken[topic]++ < per_topic) messages.push_back({topic, types[topic], {data.begin(), data.end()}});
  });
  return messages;
}

std::optional<std::filesystem::path> SharedPath(Seeds& seeds, const std::filesystem::path& relative) {
  if (!seeds.SharedHead(relative, 0, false)) return std::nullopt;
  return seeds.shared() / relative;
}

}  // namespace slamsweep::fuzz
