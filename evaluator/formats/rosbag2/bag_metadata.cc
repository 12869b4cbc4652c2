#include "evaluator/formats/rosbag2/bag_metadata.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {
namespace {

constexpr int kNewestVersion = 9;

class Fields {
 public:
  Fields(const std::filesystem::path& source) : source_(source) {}

  [[noreturn]] void Fail(const YAML::Node& node, const std::string& message) const {
    const std::size_t line = node.Mark().line >= 0 ? static_cast<std::size_t>(node.Mark().line + 1) : 0;
    throw InputError(Located(source_, line, message));
  }
  YAML::Node Required(const YAML::Node& map, const char* key, const std::string& path) const {
    const YAML::Node value = map[key];
    if (!value.IsDefined() || value.IsNull()) Fail(map, fmt::format("{}: missing '{}'", path, key));
    return value;
  }
  template <typename T>
  T As(const YAML::Node& node, const std::string& path, const char* expected) const {
    try {
      return node.as<T>();
    } catch (const YAML::Exception&) {
      Fail(node, fmt::format("{}: expected {}", path, expected));
    }
  }
  /// A field added in a later version: its default when absent.
  template <typename T>
  T Optional(const YAML::Node& map, const char* key, const std::string& path, const char* expected, T fallback) const {
    const YAML::Node value = map[key];
    if (!value.IsDefined() || value.IsNull()) return fallback;
    return As<T>(value, path + "." + key, expected);
  }
  /// {nanoseconds: N} or {nanoseconds_since_epoch: N}.
  std::int64_t Nanoseconds(const YAML::Node& map, const char* key, const char* unit, const std::string& path) const {
    const YAML::Node value = map[key];
    if (!value.IsDefined() || value.IsNull()) return 0;
    if (!value.IsMap()) Fail(value, fmt::format("{}.{}: expected a map with {}", path, key, unit));
    return Optional<std::int64_t>(value, unit, path + "." + key, "a whole number of nanoseconds", 0);
  }

 private:
  const std::filesystem::path& source_;
};

std::string QuotedYaml(const std::string& text) {
  YAML::Emitter out;
  out << YAML::DoubleQuoted << text;
  return out.c_str();
}

}  // namespace

Rosbag2Metadata ParseRosbag2Metadata(std::string_view yaml, const std::filesystem::path& source) {
  YAML::Node root;
  try {
    root = YAML::Load(std::string(yaml));
  } catch (const YAML::Exception& error) {
    throw InputError(Located(source, static_cast<std::size_t>(error.mark.line + 1), error.msg));
  }
  const Fields fields(source);
  const std::string top = "rosbag2_bagfile_information";
  if (!root.IsMap() || !root[top].IsMap()) {
    throw InputError(Located(source, 1, "expected a map '" + top + "' (a rosbag2 metadata.yaml)"));
  }
  const YAML::Node info = root[top];
  Rosbag2Metadata metadata;
  metadata.version = fields.As<int>(fields.Required(info, "version", top), top + ".version", "a whole number");
  if (metadata.version < 1 || metadata.version > kNewestVersion) {
    fields.Fail(info["version"], fmt::format("{}.version: expected 1 to {}, got {} (a newer rosbag2?)", top,
                                             kNewestVersion, metadata.version));
  }
  metadata.storage_identifier =
      fields.As<std::string>(fields.Required(info, "storage_identifier", top), top + ".storage_identifier", "text");
  const YAML::Node paths = fields.Required(info, "relative_file_paths", top);
  if (!paths.IsSequence()) fields.Fail(paths, top + ".relative_file_paths: expected a list of file names");
  for (const YAML::Node& path : paths) {
    metadata.relative_file_paths.push_back(fields.As<std::string>(path, top + ".relative_file_paths", "a file name"));
  }
  metadata.message_count = fields.Optional<std::uint64_t>(info, "message_count", top, "a whole number of messages", 0);
  metadata.duration_ns = fields.Nanoseconds(info, "duration", "nanoseconds", top);
  metadata.starting_time_ns = fields.Nanoseconds(info, "starting_time", "nanoseconds_since_epoch", top);
  metadata.compression_format = fields.Optional<std::string>(info, "compression_format", top, "text", "");
  metadata.compression_mode = fields.Optional<std::string>(info, "compression_mode", top, "text", "");
  metadata.ros_distro = fields.Optional<std::string>(info, "ros_distro", top, "text", "");
  if (const YAML::Node topics = info["topics_with_message_count"]; topics.IsDefined() && !topics.IsNull()) {
    if (!topics.IsSequence()) fields.Fail(topics, top + ".topics_with_message_count: expected a list");
    for (const YAML::Node& entry : topics) {
      const std::string path = top + ".topics_with_message_count";
      const YAML::Node topic = fields.Required(entry, "topic_metadata", path);
      Rosbag2TopicInfo topic_info;
      topic_info.name = fields.As<std::string>(fields.Required(topic, "name", path), path + ".name", "text");
      topic_info.type = fields.As<std::string>(fields.Required(topic, "type", path), path + ".type", "text");
      topic_info.serialization_format =
          fields.Optional<std::string>(topic, "serialization_format", path, "text", "cdr");
      topic_info.message_count = fields.Optional<std::uint64_t>(entry, "message_count", path, "a whole number", 0);
      metadata.topics.push_back(std::move(topic_info));
    }
  }
  if (const YAML::Node files = info["files"]; files.IsDefined() && !files.IsNull()) {
    if (!files.IsSequence()) fields.Fail(files, top + ".files: expected a list");
    for (const YAML::Node& file : files) {
      const std::string path = top + ".files";
      Rosbag2FileInfo file_info;
      file_info.path = fields.As<std::string>(fields.Required(file, "path", path), path + ".path", "a file name");
      file_info.starting_time_ns = fields.Nanoseconds(file, "starting_time", "nanoseconds_since_epoch", path);
      file_info.duration_ns = fields.Nanoseconds(file, "duration", "nanoseconds", path);
      file_info.message_count = fields.Optional<std::uint64_t>(file, "message_count", path, "a whole number", 0);
      metadata.files.push_back(std::move(file_info));
    }
  }
  return metadata;
}

std::string FormatRosbag2Metadata(const Rosbag2Metadata& metadata) {
  std::string out = "rosbag2_bagfile_information:\n";
  out += fmt::format("  version: {}\n  storage_identifier: {}\n", metadata.version, metadata.storage_identifier);
  out += fmt::format("  duration:\n    nanoseconds: {}\n", metadata.duration_ns);
  out += fmt::format("  starting_time:\n    nanoseconds_since_epoch: {}\n", metadata.starting_time_ns);
  out += fmt::format("  message_count: {}\n  topics_with_message_count:\n", metadata.message_count);
  for (const Rosbag2TopicInfo& topic : metadata.topics) {
    out += fmt::format("    - topic_metadata:\n        name: {}\n        type: {}\n        serialization_format: {}\n",
                       QuotedYaml(topic.name), topic.type, topic.serialization_format);
    out += fmt::format("        offered_qos_profiles: {}\n", QuotedYaml(topic.offered_qos_profiles));
    if (metadata.version >= 7) out += "        type_description_hash: \"\"\n";
    out += fmt::format("      message_count: {}\n", topic.message_count);
  }
  out += fmt::format("  compression_format: {}\n  compression_mode: {}\n", QuotedYaml(metadata.compression_format),
                     QuotedYaml(metadata.compression_mode));
  out += "  relative_file_paths:\n";
  for (const std::string& path : metadata.relative_file_paths) out += "    - " + QuotedYaml(path) + "\n";
  if (metadata.version >= 5) {
    out += "  files:\n";
    for (const Rosbag2FileInfo& file : metadata.files) {
      out += fmt::format("    - path: {}\n      starting_time:\n        nanoseconds_since_epoch: {}\n",
                         QuotedYaml(file.path), file.starting_time_ns);
      out += fmt::format("      duration:\n        nanoseconds: {}\n      message_count: {}\n", file.duration_ns,
                         file.message_count);
    }
  }
  if (metadata.version >= 6) out += "  custom_data: {}\n";
  if (metadata.version >= 8) out += fmt::format("  ros_distro: {}\n", QuotedYaml(metadata.ros_distro));
  return out;
}

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
