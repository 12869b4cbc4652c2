#include "evaluator/formats/rosbag2/rosbag2_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "evaluator/formats/bag/bag_sequence.h"
#include "evaluator/formats/bag/bag_trajectory.h"
#include "evaluator/formats/rosbag2/compression.h"
#include "evaluator/formats/rosbag2/ros2_messages.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {
namespace {

constexpr const char* kMetadataFile = "metadata.yaml";
constexpr std::string_view kZstdSuffix = ".zstd";

bool IsDirectory(const std::filesystem::path& path) {
  std::error_code error;
  return std::filesystem::is_directory(path, error);
}

bool IsFile(const std::filesystem::path& path) {
  std::error_code error;
  return std::filesystem::is_regular_file(path, error);
}

/// The folder `path` names, without a trailing separator.
std::filesystem::path FolderOf(const std::filesystem::path& path) {
  return path.has_filename() ? path : path.parent_path();
}

Rosbag2Metadata ReadMetadata(const std::filesystem::path& folder) {
  const std::filesystem::path file = folder / kMetadataFile;
  if (!IsFile(file)) {
    throw InputError(
        fmt::format("{}: no {} in the folder (a rosbag2 bag folder holds metadata.yaml beside its "
                    ".db3 or .mcap files)",
                    folder.string(), kMetadataFile));
  }
  Rosbag2Metadata metadata = ParseRosbag2Metadata(ReadTextFile(file), file);
  if (metadata.relative_file_paths.empty()) {
    throw InputError(Located(file, 0, "relative_file_paths lists no file: the bag has no data"));
  }
  if (!metadata.compression_format.empty() && metadata.compression_format != "zstd") {
    throw InputError(Located(
        file, 0,
        fmt::format("unknown compression_format '{}' (rosbag2 compresses with zstd)", metadata.compression_format)));
  }
  const std::string& mode = metadata.compression_mode;
  if (!mode.empty() && mode != "NONE" && mode != "FILE" && mode != "MESSAGE") {
    throw InputError(Located(file, 0, fmt::format("unknown compression_mode '{}' (expected FILE or MESSAGE)", mode)));
  }
  return metadata;
}

/// The split file a metadata entry names, which must be there.
std::filesystem::path SplitFile(const std::filesystem::path& folder, const std::string& relative) {
  // A bag's files lie in its folder: a metadata.yaml naming another place (an absolute path, "..") would make
  // slamsweep read, and report on, files a bag has no business with.
  const std::filesystem::path named(relative);
  const bool escapes =
      named.has_root_path() || std::any_of(named.begin(), named.end(), [](const auto& part) { return part == ".."; });
  if (relative.empty() || escapes) {
    throw InputError(fmt::format("{}: split file '{}' named by {} is not a file inside the bag folder", folder.string(),
                                 relative, kMetadataFile));
  }
  // Bags written before rosbag2 stored relative names (Foxy and older) hold "folder/file".
  std::filesystem::path file = folder / relative;
  if (!IsFile(file) && !std::filesystem::path(relative).parent_path().empty()) {
    file = folder / std::filesystem::path(relative).filename();
  }
  if (!IsFile(file)) {
    throw InputError(fmt::format("{}: split file {} named by {} is missing", folder.string(), relative, kMetadataFile));
  }
  return file;
}

bool EndsWith(const std::string& text, std::string_view suffix) { return text.ends_with(suffix); }

std::string Where(const std::filesystem::path& file, const std::string& topic, std::size_t index) {
  return fmt::format("{}: topic '{}' message {}", file.string(), topic, index);
}

}  // namespace

Rosbag2Bag::Rosbag2Bag(const std::filesystem::path& path) : path_(path) {
  if (IsDirectory(path)) {
    const std::filesystem::path folder = FolderOf(path);
    const Rosbag2Metadata metadata = ReadMetadata(folder);
    compression_mode_ = metadata.compression_format.empty() ? "" : metadata.compression_mode;
    for (const std::string& relative : metadata.relative_file_paths) {
      const bool whole_file = compression_mode_ == "FILE" || EndsWith(relative, kZstdSuffix);
      files_.push_back(Rosbag2File::Open(SplitFile(folder, relative), metadata.storage_identifier, whole_file));
    }
  } else {
    if (!IsFile(path)) throw InputError(Located(path, 0, "no such ROS 2 bag (a bag folder, or a .db3 or .mcap file)"));
    files_.push_back(Rosbag2File::Open(path, "", EndsWith(path.filename().string(), kZstdSuffix)));
  }
  std::map<std::string, BagTopic> topics;
  bool first = true;
  for (const auto& file : files_) {
    for (const StorageTopic& topic : file->Topics()) {
      BagTopic& merged = topics[topic.name];
      merged.topic = topic.name;
      if (merged.datatype.empty()) {
        merged.datatype = topic.type;
      } else if (merged.datatype != topic.type) {
        merged.datatype += ", " + topic.type;
      }
      merged.message_count += topic.message_count;
      summary_.message_count += topic.message_count;
    }
    if (file->StartNs() != 0 || file->EndNs() != 0) {
      summary_.start_s = first ? file->StartNs() / 1e9 : std::min(summary_.start_s, file->StartNs() / 1e9);
      summary_.end_s = std::max(summary_.end_s, file->EndNs() / 1e9);
      first = false;
    }
    summary_.notes.insert(summary_.notes.end(), file->Notes().begin(), file->Notes().end());
  }
  for (auto& [name, topic] : topics) summary_.topics.push_back(std::move(topic));
}

std::string Rosbag2Bag::Name() const {
  if (IsDirectory(path_)) return FolderOf(path_).filename().string();
  std::string name = path_.filename().string();
  if (EndsWith(name, kZstdSuffix)) name.resize(name.size() - kZstdSuffix.size());
  return std::filesystem::path(name).stem().string();
}

BagMessages Rosbag2Bag::ReadMessages(const BagRequest& request) const {
  BagMessages messages;
  std::map<std::string, BagMessageKind> kinds;
  if (!request.scan_topic.empty()) kinds[request.scan_topic] = BagMessageKind::kLaserScan;
  for (const std::string& topic : request.pose_topics) {
    messages.poses[topic];
    const auto found = std::find_if(summary_.topics.begin(), summary_.topics.end(),
                                    [&](const BagTopic& t) { return t.topic == topic; });
    kinds[topic] = found != summary_.topics.end() ? KindOfDatatype(found->datatype) : BagMessageKind::kOther;
  }
  if (request.read_tf) {
    kinds[kTfTopic] = BagMessageKind::kTfMessage;
    kinds[kTfStaticTopic] = BagMessageKind::kTfMessage;
  }
  std::set<std::string> wanted;
  for (const auto& [topic, kind] : kinds) wanted.insert(topic);
  for (const auto& file : files_) {
    for (const StorageTopic& topic : file->Topics()) {
      if (wanted.count(topic.name) > 0 && topic.encoding != "cdr") {
        throw InputError(
            fmt::format("{}: topic '{}' is serialised as '{}'; slamsweep reads cdr, the encoding "
                        "rosbag2 records",
                        file->Path().string(), topic.name, topic.encoding));
      }
      if (wanted.count(topic.name) > 0 && KindOfDatatype(topic.type) != kinds.at(topic.name)) {
        throw InputError(fmt::format("{}: topic '{}' holds {}, expected {}", file->Path().string(), topic.name,
                                     topic.type, Ros2TypeName(kinds.at(topic.name))));
      }
    }
    std::map<std::string, std::size_t> counts;
    std::vector<std::uint8_t> inflated;
    file->ReadMessages(wanted,
                       [&](const std::string& topic, std::int64_t log_time_ns, std::span<const std::uint8_t> data) {
                         const std::string where = Where(file->Path(), topic, counts[topic]++);
                         if (compression_mode_ == "MESSAGE") {
                           inflated = ZstdDecompress(data, where + " (rosbag2 per-message zstd compression)");
                           data = inflated;
                         }
                         const double record_s = static_cast<double>(log_time_ns) / 1e9;
                         const BagMessageKind kind = kinds.at(topic);
                         if (kind == BagMessageKind::kLaserScan) {
                           messages.scans.push_back(DecodeLaserScan(data, record_s, where));
                         } else if (kind == BagMessageKind::kTfMessage) {
                           DecodeTfMessage(data, record_s, where, topic == kTfTopic ? messages.tf : messages.tf_static);
                         } else {
                           messages.poses[topic].push_back(DecodeStampedPose(kind, data, record_s, where));
                         }
                       });
  }
  return messages;
}

std::vector<std::filesystem::path> Rosbag2Files(const std::filesystem::path& path) {
  if (!IsDirectory(path)) {
    if (!IsFile(path)) throw InputError(Located(path, 0, "no such ROS 2 bag (a bag folder, or a .db3 or .mcap file)"));
    return {path};
  }
  const std::filesystem::path folder = FolderOf(path);
  std::vector<std::filesystem::path> files = {folder / kMetadataFile};
  for (const std::string& relative : ReadMetadata(folder).relative_file_paths) {
    files.push_back(SplitFile(folder, relative));
  }
  return files;
}

Sequence ReadRosbag2(const std::filesystem::path& path, const BagReadOptions& options) {
  const Rosbag2Bag bag(path);
  BagReadOptions named = options;
  if (named.name.empty()) named.name = bag.Name();
  return ReadBagSequence(
      path, bag.Summary(), [&](const BagRequest& request) { return bag.ReadMessages(request); }, named);
}

Trajectory ReadRosbag2Trajectory(const std::filesystem::path& path, std::string_view selector,
                                 std::vector<std::string>& warnings) {
  const Rosbag2Bag bag(path);
  warnings.insert(warnings.end(), bag.Summary().notes.begin(), bag.Summary().notes.end());
  return ReadBagTrajectory(
      path, bag.Summary(), [&](const BagRequest& request) { return bag.ReadMessages(request); }, selector, warnings);
}

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
