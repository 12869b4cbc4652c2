#include "evaluator/formats/rosbag2/rosbag2_storage.h"

#include <fmt/format.h>

#include <cstring>
#include <fstream>
#include <map>
#include <optional>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/rosbag2/compression.h"
#include "evaluator/formats/rosbag2/mapped_file.h"
#include "evaluator/formats/rosbag2/mcap_reader.h"
#include "evaluator/formats/rosbag2/sqlite_bag.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {
namespace {

constexpr char kSqliteMagic[] = "SQLite format 3";  // with its NUL: 16 bytes

/// Bytes of the file: mapped, or inflated from zstd.
struct FileBytes {
  std::optional<MappedFile> mapped;
  std::vector<std::uint8_t> inflated;
  std::span<const std::uint8_t> Bytes() const { return mapped ? mapped->Bytes() : std::span(inflated); }
};

FileBytes LoadBytes(const std::filesystem::path& path, bool whole_file_zstd) {
  FileBytes bytes;
  bytes.mapped.emplace(path);
  if (whole_file_zstd) {
    bytes.inflated = ZstdDecompress(bytes.mapped->Bytes(), path.string() + " (rosbag2 per-file zstd compression)");
    bytes.mapped.reset();
  }
  return bytes;
}

std::string StorageOf(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
  if (bytes.size() >= sizeof(kMcapMagic) && std::memcmp(bytes.data(), kMcapMagic, sizeof(kMcapMagic)) == 0) {
    return "mcap";
  }
  if (bytes.size() >= sizeof(kSqliteMagic) && std::memcmp(bytes.data(), kSqliteMagic, sizeof(kSqliteMagic)) == 0) {
    return "sqlite3";
  }
  throw InputError(Located(path, 0, "neither an MCAP file nor an SQLite database (a rosbag2 storage file)"));
}

/// Joins the types of a topic's channels.
void AddType(StorageTopic& topic, const std::string& type) {
  if (topic.type.empty()) {
    topic.type = type;
  } else if ((", " + topic.type + ", ").find(", " + type + ", ") == std::string::npos) {
    topic.type += ", " + type;
  }
}

std::vector<StorageTopic> ByName(std::map<std::string, StorageTopic> topics) {
  std::vector<StorageTopic> sorted;
  for (auto& [name, topic] : topics) sorted.push_back(std::move(topic));
  return sorted;
}

class McapFile final : public Rosbag2File {
 public:
  McapFile(const std::filesystem::path& path, FileBytes bytes)
      : Rosbag2File(path), bytes_(std::move(bytes)), reader_(bytes_.Bytes(), path.string()) {
    const McapContents& contents = reader_.Contents();
    std::map<std::string, StorageTopic> topics;
    for (const auto& [id, channel] : contents.channels) {
      StorageTopic& topic = topics[channel.topic];
      topic.name = channel.topic;
      const auto schema = contents.schemas.find(channel.schema_id);
      AddType(topic, schema != contents.schemas.end() ? schema->second.name : "(no schema)");
      topic.encoding = channel.message_encoding;
      const auto count = contents.message_counts.find(id);
      if (count != contents.message_counts.end()) topic.message_count += count->second;
    }
    topics_ = ByName(std::move(topics));
    start_ns_ = static_cast<std::int64_t>(contents.start_ns);
    end_ns_ = static_cast<std::int64_t>(contents.end_ns);
    notes_ = contents.notes;
  }

  void ReadMessages(const std::set<std::string>& topics, const StorageVisitor& visit) const override {
    std::set<std::uint16_t> channels;
    for (const auto& [id, channel] : reader_.Contents().channels) {
      if (topics.count(channel.topic) > 0) channels.insert(id);
    }
    reader_.ReadMessages(channels, [&](const McapMessage& message) {
      visit(reader_.Contents().channels.at(message.channel_id).topic, static_cast<std::int64_t>(message.log_time_ns),
            message.data);
    });
  }

 private:
  FileBytes bytes_;
  McapReader reader_;
};

class SqliteFile final : public Rosbag2File {
 public:
  SqliteFile(const std::filesystem::path& path, SqliteBag bag) : Rosbag2File(path), bag_(std::move(bag)) {
    std::map<std::string, StorageTopic> topics;
    for (const SqliteTopic& row : bag_.Topics()) {
      StorageTopic& topic = topics[row.name];
      topic.name = row.name;
      AddType(topic, row.type);
      topic.encoding = row.serialization_format;
      topic.message_count += row.message_count;
      names_[row.id] = row.name;
    }
    topics_ = ByName(std::move(topics));
    start_ns_ = bag_.StartNs();
    end_ns_ = bag_.EndNs();
  }

  void ReadMessages(const std::set<std::string>& topics, const StorageVisitor& visit) const override {
    std::set<std::int64_t> ids;
    for (const auto& [id, name] : names_) {
      if (topics.count(name) > 0) ids.insert(id);
    }
    bag_.ReadMessages(ids, [&](std::int64_t topic_id, std::int64_t timestamp_ns, std::span<const std::uint8_t> data) {
      visit(names_.at(topic_id), timestamp_ns, data);
    });
  }

 private:
  SqliteBag bag_;
  std::map<std::int64_t, std::string> names_;
};

}  // namespace

std::unique_ptr<Rosbag2File> Rosbag2File::Open(const std::filesystem::path& path, const std::string& storage,
                                               bool whole_file_zstd) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw InputError(Located(path, 0, "no such bag file"));
  if (!storage.empty() && storage != "mcap" && storage != "sqlite3") {
    throw InputError(Located(path, 0, fmt::format("unknown rosbag2 storage '{}' (expected sqlite3 or mcap)", storage)));
  }
  FileBytes bytes = LoadBytes(path, whole_file_zstd);
  const std::string found = StorageOf(path, bytes.Bytes());
  if (!storage.empty() && found != storage) {
    throw InputError(Located(path, 0, fmt::format("metadata.yaml says storage {}, the file is {}", storage, found)));
  }
  if (found == "mcap") return std::make_unique<McapFile>(path, std::move(bytes));
  // SQLite reads a file itself; an inflated one from memory.
  SqliteBag bag =
      whole_file_zstd ? SqliteBag::FromBytes(std::move(bytes.inflated), path.string()) : SqliteBag::Open(path);
  return std::make_unique<SqliteFile>(path, std::move(bag));
}

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
