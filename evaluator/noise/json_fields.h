#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace slamsweep::evaluator::inline noise {

/// Reads the fields of one JSON object of options strictly: a field of the wrong type is an
/// InputError naming its full path ("odometry_noise.alpha1: expected a number, got \"x\""), a
/// missing field keeps its default, and Finish() rejects any field nobody asked for, so a
/// typo in a sweep file stops the sweep instead of silently running with defaults.
/// Throws InputError "<prefix><field> = <value>, expected <expected>" unless `ok`.
void RequireNoiseField(const std::string& prefix, bool ok, const char* field, double value, const char* expected);

class JsonFields {
 public:
  /// `path` names the object in messages ("odometry_noise"); throws unless `object` is an object.
  JsonFields(const nlohmann::json& object, std::string path);

  double Number(std::string_view key, double fallback);
  std::uint64_t Unsigned(std::string_view key, std::uint64_t fallback);
  int Integer(std::string_view key, int fallback);
  std::string Text(std::string_view key, const std::string& fallback);
  bool Bool(std::string_view key, bool fallback);
  /// The sub-object at `key`, or nullptr when it is absent (throws when it is not an object).
  const nlohmann::json* Object(std::string_view key);
  /// "path.key", for messages about a field's value.
  std::string PathOf(std::string_view key) const;
  /// Throws InputError listing the first field that was never read.
  void Finish() const;

 private:
  const nlohmann::json* Find(std::string_view key);

  const nlohmann::json& object_;
  std::string path_;
  std::set<std::string, std::less<>> read_;
};

}  // namespace slamsweep::evaluator::inline noise
