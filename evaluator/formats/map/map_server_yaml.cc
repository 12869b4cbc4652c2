#include "evaluator/formats/map/map_server_yaml.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline map {
namespace {

constexpr std::array<std::string_view, 7> kKeys = {"image",           "resolution",  "origin", "negate",
                                                   "occupied_thresh", "free_thresh", "mode"};
constexpr std::string_view kKeyList = "image, resolution, origin, negate, occupied_thresh, free_thresh, mode";

std::size_t LineOf(const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? 0 : static_cast<std::size_t>(mark.line) + 1;
}

/// One `key: value` of the YAML, with where it is, so that every error can point at it.
struct Field {
  const std::filesystem::path* file = nullptr;
  std::string_view key;
  YAML::Node value;
  std::size_t line = 0;

  [[noreturn]] void Fail(std::string_view expected, const YAML::Node& at) const {
    std::string got;
    if (at.IsScalar()) {
      got = fmt::format(", got '{}'", at.Scalar());
    } else if (at.IsNull()) {
      got = ", got nothing";
    } else if (at.IsSequence()) {
      got = ", got a list";
    } else if (at.IsMap()) {
      got = ", got a mapping";
    }
    // A missing value has no place of its own (yaml-cpp marks the next token): use the key's line.
    const std::size_t where = (at.IsNull() || LineOf(at) == 0) ? line : LineOf(at);
    throw InputError(Located(*file, where, fmt::format("field '{}': expected {}{}", key, expected, got)));
  }
  [[noreturn]] void Fail(std::string_view expected) const { Fail(expected, value); }
};

std::optional<double> ParseNumber(const YAML::Node& node) {
  if (!node.IsScalar()) return std::nullopt;
  std::string_view text = node.Scalar();
  if (text.starts_with('+')) text.remove_prefix(1);  // YAML allows it, from_chars does not
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

double Number(const Field& field, const YAML::Node& node, std::string_view expected) {
  const std::optional<double> value = ParseNumber(node);
  if (!value) field.Fail(expected, node);
  return *value;
}

double Probability(const Field& field) {
  constexpr std::string_view kExpected = "a number in [0, 1]";
  const double value = Number(field, field.value, kExpected);
  if (value < 0.0 || value > 1.0) field.Fail(kExpected);
  return value;
}

bool Negate(const Field& field) {
  constexpr std::string_view kExpected = "0 or 1";
  if (!field.value.IsScalar()) field.Fail(kExpected);
  const std::string& text = field.value.Scalar();
  if (text == "0" || text == "false" || text == "False" || text == "FALSE") return false;
  if (text == "1" || text == "true" || text == "True" || text == "TRUE") return true;
  field.Fail(kExpected);
}

MapServerMode Mode(const Field& field) {
  constexpr std::string_view kExpected = "trinary, scale or raw";
  if (!field.value.IsScalar()) field.Fail(kExpected);
  const std::string& text = field.value.Scalar();
  if (text == "trinary") return MapServerMode::kTrinary;
  if (text == "scale") return MapServerMode::kScale;
  if (text == "raw") return MapServerMode::kRaw;
  field.Fail(kExpected);
}

GridOrigin Origin(const Field& field) {
  constexpr std::string_view kExpected = "[x, y, yaw] (three numbers: metres, metres, radians)";
  if (!field.value.IsSequence() || field.value.size() != 3) field.Fail(kExpected);
  GridOrigin origin;
  origin.x_m = Number(field, field.value[0], kExpected);
  origin.y_m = Number(field, field.value[1], kExpected);
  origin.yaw_rad = Number(field, field.value[2], kExpected);
  return origin;
}

}  // namespace

std::string_view MapServerModeName(MapServerMode mode) {
  switch (mode) {
    case MapServerMode::kTrinary:
      return "trinary";
    case MapServerMode::kScale:
      return "scale";
    case MapServerMode::kRaw:
      return "raw";
  }
  return "trinary";
}

MapServerMetadata ParseMapServerYaml(std::string_view content, const std::filesystem::path& yaml_path) {
  YAML::Node root;
  try {
    root = YAML::Load(std::string(content));
  } catch (const YAML::Exception& error) {
    const std::size_t line = error.mark.is_null() ? 0 : static_cast<std::size_t>(error.mark.line) + 1;
    throw InputError(Located(yaml_path, line, "invalid YAML: " + error.msg));
  }
  if (!root.IsDefined() || root.IsNull()) {
    throw InputError(Located(yaml_path, 0, fmt::format("empty map YAML; expected the map_server keys {}", kKeyList)));
  }
  if (!root.IsMap()) {
    throw InputError(
        Located(yaml_path, LineOf(root),
                fmt::format("expected a mapping of map_server keys ({}), not a single value or list", kKeyList)));
  }

  std::map<std::string, Field, std::less<>> fields;
  for (const auto& entry : root) {
    const std::size_t line = LineOf(entry.first);
    if (!entry.first.IsScalar()) throw InputError(Located(yaml_path, line, "expected a key name"));
    const std::string& name = entry.first.Scalar();
    const auto known = std::find(kKeys.begin(), kKeys.end(), name);
    if (known == kKeys.end()) {
      throw InputError(Located(yaml_path, line, fmt::format("unknown key '{}' (map_server keys: {})", name, kKeyList)));
    }
    if (fields.contains(name)) {
      throw InputError(Located(yaml_path, line,
                               fmt::format("key '{}' appears twice (first on line {})", name, fields.at(name).line)));
    }
    fields.emplace(name, Field{&yaml_path, *known, entry.second, line});
  }
  const auto required = [&](std::string_view key, std::string_view expected) -> const Field& {
    const auto found = fields.find(key);
    if (found == fields.end()) {
      throw InputError(Located(yaml_path, 0, fmt::format("field '{}' is missing; expected {}", key, expected)));
    }
    return found->second;
  };

  MapServerMetadata metadata;
  const Field& image = required("image", "the image file name");
  if (!image.value.IsScalar() || image.value.Scalar().empty()) image.Fail("the image file name (a non-empty string)");
  const std::filesystem::path image_path(image.value.Scalar());
  // map_server resolves a relative image name against the folder of the YAML file.
  metadata.image = image_path.is_absolute() ? image_path : yaml_path.parent_path() / image_path;
  metadata.image_line = image.line;

  const Field& resolution = required("resolution", "a positive number");
  metadata.resolution_m = Number(resolution, resolution.value, "a positive number");
  if (metadata.resolution_m <= 0.0) resolution.Fail("a positive number");

  metadata.origin = Origin(required("origin", "[x, y, yaw]"));
  metadata.negate = Negate(required("negate", "0 or 1"));
  if (const auto mode = fields.find("mode"); mode != fields.end()) metadata.mode = Mode(mode->second);

  metadata.occupied_thresh = Probability(required("occupied_thresh", "a number in [0, 1]"));
  const Field& free_thresh = required("free_thresh", "a number in [0, 1]");
  metadata.free_thresh = Probability(free_thresh);
  if (metadata.mode == MapServerMode::kScale && !(metadata.free_thresh < metadata.occupied_thresh)) {
    free_thresh.Fail(fmt::format("a number below occupied_thresh ({}) in scale mode", metadata.occupied_thresh));
  }
  if (metadata.free_thresh > metadata.occupied_thresh) {
    free_thresh.Fail(fmt::format("a number not above occupied_thresh ({})", metadata.occupied_thresh));
  }
  return metadata;
}

}  // namespace slamsweep::evaluator::inline formats::inline map
