#include "orchestrator/config/yaml_fields.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator::inline config {
namespace {

bool IsQuoted(const YAML::Node& node) { return node.Tag() == "!"; }

std::optional<long long> AsInteger(const std::string& text) {
  long long value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end || text.empty()) return std::nullopt;
  return value;
}

std::optional<double> AsNumber(const std::string& text) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && std::isfinite(value)) return value;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

}  // namespace

std::string LocatedAt(const std::filesystem::path& file, const YAML::Node& node, std::string_view message) {
  const YAML::Mark mark = node.IsDefined() ? node.Mark() : YAML::Mark::null_mark();
  if (mark.is_null()) return fmt::format("{}: {}", file.string(), message);
  return fmt::format("{}:{}:{}: {}", file.string(), mark.line + 1, mark.column + 1, message);
}

void FailAt(const std::filesystem::path& file, const YAML::Node& node, std::string_view message) {
  throw evaluator::InputError(LocatedAt(file, node, message));
}

void FailExpected(const std::filesystem::path& file, const YAML::Node& node, std::string_view path,
                  std::string_view expected) {
  FailAt(file, node, fmt::format("{}: expected {}, got {}", path, expected, Describe(node)));
}

std::string Describe(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsMap()) return "a map";
  if (node.IsSequence()) return "a list";
  return "'" + node.Scalar() + "'";
}

nlohmann::json YamlToJson(const YAML::Node& node) {
  if (node.IsMap()) {
    nlohmann::json object = nlohmann::json::object();
    for (const auto& item : node) object[item.first.Scalar()] = YamlToJson(item.second);
    return object;
  }
  if (node.IsSequence()) {
    nlohmann::json array = nlohmann::json::array();
    for (const auto& item : node) array.push_back(YamlToJson(item));
    return array;
  }
  if (!node.IsScalar()) return nullptr;
  const std::string& text = node.Scalar();
  if (IsQuoted(node)) return text;
  if (text == "true" || text == "false") return text == "true";
  if (const auto integer = AsInteger(text)) return *integer;
  if (const auto number = AsNumber(text)) return *number;
  return text;
}

YamlFields::YamlFields(const std::filesystem::path& file, const YAML::Node& node, std::string path)
    : file_(file), node_(node), path_(std::move(path)) {
  if (!node_.IsMap()) FailExpected(file_, node_, path_.empty() ? "(top level)" : path_, "a map");
}

std::string YamlFields::PathOf(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

bool YamlFields::Has(std::string_view key) const {
  const YAML::Node value = node_[std::string(key)];
  return value.IsDefined();
}

YAML::Node YamlFields::Get(std::string_view key) {
  known_.emplace(key);
  // operator[] on a const node never inserts.
  const YAML::Node& map = node_;
  return map[std::string(key)];
}

std::string YamlFields::Text(std::string_view key, const std::string& fallback) {
  const YAML::Node value = Get(key);
  if (!value.IsDefined() || value.IsNull()) return fallback;
  if (!value.IsScalar()) FailExpected(file_, value, PathOf(key), "a text value");
  return value.Scalar();
}

std::string YamlFields::RequiredText(std::string_view key) {
  const YAML::Node value = Get(key);
  if (!value.IsDefined()) FailAt(file_, node_, fmt::format("{}: missing (required)", PathOf(key)));
  if (!value.IsScalar() || value.Scalar().empty()) FailExpected(file_, value, PathOf(key), "a non-empty text value");
  return value.Scalar();
}

double YamlFields::Number(std::string_view key, double fallback) {
  const YAML::Node value = Get(key);
  if (!value.IsDefined() || value.IsNull()) return fallback;
  const std::optional<double> number = value.IsScalar() && !IsQuoted(value) ? AsNumber(value.Scalar()) : std::nullopt;
  if (!number) FailExpected(file_, value, PathOf(key), "a finite number");
  return *number;
}

std::uint64_t YamlFields::Unsigned(std::string_view key, std::uint64_t fallback) {
  const YAML::Node value = Get(key);
  if (!value.IsDefined() || value.IsNull()) return fallback;
  std::uint64_t number = 0;
  bool ok = value.IsScalar() && !IsQuoted(value) && !value.Scalar().empty();
  if (ok) {
    const std::string& text = value.Scalar();
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, number);
    ok = error == std::errc() && stop == end;
  }
  if (!ok) FailExpected(file_, value, PathOf(key), "a whole number >= 0");
  return number;
}

bool YamlFields::Bool(std::string_view key, bool fallback) {
  const YAML::Node value = Get(key);
  if (!value.IsDefined() || value.IsNull()) return fallback;
  if (!value.IsScalar() || (value.Scalar() != "true" && value.Scalar() != "false")) {
    FailExpected(file_, value, PathOf(key), "true or false");
  }
  return value.Scalar() == "true";
}

void YamlFields::Finish() const {
  for (const auto& item : node_) {
    const std::string key = item.first.Scalar();
    if (known_.contains(key)) continue;
    std::string known;
    for (const std::string& name : known_) known += (known.empty() ? "" : ", ") + name;
    FailAt(file_, item.first, fmt::format("{}: unknown key (expected one of: {})", PathOf(key), known));
  }
}

}  // namespace slamsweep::orchestrator::inline config
