#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <set>
#include <span>
#include <string>
#include <vector>

namespace slamsweep::evaluator::inline formats::inline rosbag2 {

/// A topic as one storage file records it. A topic recorded under several types lists them joined by ", ".
struct StorageTopic {
  std::string name;
  std::string type;
  /// The serialisation ("cdr").
  std::string encoding;
  std::uint64_t message_count = 0;
};

/// Receives one message: its topic, the time the bag recorded it (ns) and its serialised data.
using StorageVisitor =
    std::function<void(const std::string& topic, std::int64_t log_time_ns, std::span<const std::uint8_t> data)>;

/// One storage file of a rosbag2 bag (a split file): an MCAP file or an sqlite3 database.
class Rosbag2File {
 public:
  /// Opens `path`. `storage` is "mcap" or "sqlite3" (metadata.yaml's storage_identifier), or empty to
  /// tell by the file's content. With `whole_file_zstd` (rosbag2's per-file compression) the file is
  /// inflated in memory first. Throws InputError naming the file when it is missing, unreadable, of
  /// an unknown storage, or damaged.
  static std::unique_ptr<Rosbag2File> Open(const std::filesystem::path& path, const std::string& storage,
                                           bool whole_file_zstd);
  virtual ~Rosbag2File() = default;

  const std::filesystem::path& Path() const { return path_; }
  /// By name.
  const std::vector<StorageTopic>& Topics() const { return topics_; }
  /// Record times of the first and last message (ns); 0 when there are none.
  std::int64_t StartNs() const { return start_ns_; }
  std::int64_t EndNs() const { return end_ns_; }
  /// What the reader noticed (a damaged MCAP index it read around).
  const std::vector<std::string>& Notes() const { return notes_; }

  /// Visits every message on `topics`, in the file's order.
  virtual void ReadMessages(const std::set<std::string>& topics, const StorageVisitor& visit) const = 0;

 protected:
  explicit Rosbag2File(std::filesystem::path path) : path_(std::move(path)) {}

  std::filesystem::path path_;
  std::vector<StorageTopic> topics_;
  std::int64_t start_ns_ = 0;
  std::int64_t end_ns_ = 0;
  std::vector<std::string> notes_;
};

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
