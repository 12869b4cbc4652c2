#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <span>
#include <string>
#include <vector>

struct sqlite3;

namespace slamsweep::evaluator::inline formats::inline rosbag2 {

/// A prepared SQLite statement (sqlite_bag.cc).
struct SqliteStatement;

struct SqliteTopic {
  std::int64_t id = 0;
  std::string name;
  std::string type;
  std::string serialization_format;
  std::uint64_t message_count = 0;
};

/// A rosbag2 sqlite3 storage file (.db3), read-only. Schema versions 1 to 4 differ in their tables
/// and columns (1: no schema table; 2: schema table and topics.offered_qos_profiles; 3: a metadata
/// table; 4: message_definitions and topics.type_description_hash): only the columns every version
/// has are read, after checking they are there (PRAGMA table_info). Errors are InputErrors naming the
/// file, and the table or SQLite's reason.
class SqliteBag {
 public:
  /// Opens the file read-only and immutable (no lock, no journal written beside a bag that may lie on
  /// a read-only disk).
  static SqliteBag Open(const std::filesystem::path& path);
  /// A database held in memory (a file inflated from rosbag2's per-file zstd); `name` for messages.
  static SqliteBag FromBytes(std::vector<std::uint8_t> bytes, std::string name);

  SqliteBag(SqliteBag&&) noexcept;
  SqliteBag& operator=(SqliteBag&&) noexcept;
  ~SqliteBag();

  /// The schema table's version; 1 for files without one.
  int SchemaVersion() const { return schema_version_; }
  /// Every topic with its message count, by id.
  const std::vector<SqliteTopic>& Topics() const { return topics_; }
  /// Receive times (ns) of the first and last message; 0 when there are none.
  std::int64_t StartNs() const { return start_ns_; }
  std::int64_t EndNs() const { return end_ns_; }

  /// Calls `visit(topic_id, timestamp_ns, data)` for every message of `topic_ids`, by timestamp
  /// (then by id). `data` is valid during the call.
  void ReadMessages(const std::set<std::int64_t>& topic_ids,
                    const std::function<void(std::int64_t, std::int64_t, std::span<const std::uint8_t>)>& visit) const;

 private:
  SqliteBag(sqlite3* db, std::string name, std::unique_ptr<std::vector<std::uint8_t>> bytes);
  void Load();

  sqlite3* db_ = nullptr;
  std::string name_;
  /// The database's bytes, for one deserialised from memory (SQLite reads them in place).
  std::unique_ptr<std::vector<std::uint8_t>> bytes_;
  int schema_version_ = 1;
  std::vector<SqliteTopic> topics_;
  std::int64_t start_ns_ = 0;
  std::int64_t end_ns_ = 0;
};

/// Writes a rosbag2 sqlite3 file as ROS 2 Humble does (schema version 3: tables schema, metadata,
/// topics with offered_qos_profiles, messages; the timestamp index).
class SqliteBagWriter {
 public:
  /// Creates `path` (an existing file is an error). Throws InputError naming the file.
  SqliteBagWriter(const std::filesystem::path& path, const std::string& ros_distro);
  ~SqliteBagWriter();
  SqliteBagWriter(const SqliteBagWriter&) = delete;
  SqliteBagWriter& operator=(const SqliteBagWriter&) = delete;

  /// Returns the topic's id.
  std::int64_t AddTopic(const std::string& name, const std::string& type, const std::string& offered_qos_profiles);
  void AddMessage(std::int64_t topic_id, std::int64_t timestamp_ns, std::span<const std::uint8_t> data);
  /// The bag's metadata (metadata.yaml's text and version) in the metadata table, then commits and closes.
  void Finish(int metadata_version, const std::string& metadata_yaml);

 private:
  void Execute(const std::string& sql);

  sqlite3* db_ = nullptr;
  std::filesystem::path path_;
  std::unique_ptr<SqliteStatement> insert_message_;
};

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
