#pragma once

#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

namespace slamsweep::orchestrator::inline config {

/// "FILE:LINE:COLUMN: message" at `node` (yaml-cpp counts from 0, editors from 1).
std::string LocatedAt(const std::filesystem::path& file, const YAML::Node& node, std::string_view message);

/// Throws InputError "FILE:LINE:COLUMN: path: expected <expected>, got <what the node holds>".
[[noreturn]] void FailExpected(const std::filesystem::path& file, const YAML::Node& node, std::string_view path,
                               std::string_view expected);
/// Throws InputError "FILE:LINE:COLUMN: message".
[[noreturn]] void FailAt(const std::filesystem::path& file, const YAML::Node& node, std::string_view message);

/// A short rendering of a node for "got ..." (a scalar's text, "a list", "a map", "nothing").
std::string Describe(const YAML::Node& node);

/// A YAML scalar as JSON: true/false -> bool, integers -> integer, other numbers -> number, anything
/// else (and every quoted scalar: "40" stays text) -> string. Maps and lists convert recursively.
nlohmann::json YamlToJson(const YAML::Node& node);

/// Reads one YAML map strictly: a wrong type is an error at the value, and Finish() rejects a key
/// nobody asked for at the key itself, listing the known keys, so a typo stops a sweep before it runs.
class YamlFields {
 public:
  /// `path` names the map in messages ("algorithms[1]"); throws unless `node` is a map.
  YamlFields(const std::filesystem::path& file, const YAML::Node& node, std::string path);

  /// The value at `key` (an invalid node when absent); marks the key as known.
  YAML::Node Get(std::string_view key);
  bool Has(std::string_view key) const;

  std::string Text(std::string_view key, const std::string& fallback);
  /// Like Text, but an absent or empty value is an error.
  std::string RequiredText(std::string_view key);
  double Number(std::string_view key, double fallback);
  std::uint64_t Unsigned(std::string_view key, std::uint64_t fallback);
  bool Bool(std::string_view key, bool fallback);

  /// "path.key", for messages.
  std::string PathOf(std::string_view key) const;
  const std::filesystem::path& file() const { return file_; }
  const YAML::Node& node() const { return node_; }
  void Finish() const;

 private:
  std::filesystem::path file_;
  YAML::Node node_;
  std::string path_;
  std::set<std::string, std::less<>> known_;
};

}  // namespace slamsweep::orchestrator::inline config
