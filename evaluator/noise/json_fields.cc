#include "evaluator/noise/json_fields.h"

#include <limits>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline noise {
namespace {

[[noreturn]] void FailType(const std::string& path, std::string_view expected, const nlohmann::json& value) {
  throw InputError(path + ": expected " + std::string(expected) + ", got " + value.dump());
}

}  // namespace

JsonFields::JsonFields(const nlohmann::json& object, std::string path) : object_(object), path_(std::move(path)) {
  if (!object_.is_object()) FailType(path_, "an object of options", object_);
}

std::string JsonFields::PathOf(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

const nlohmann::json* JsonFields::Find(std::string_view key) {
  read_.emplace(key);
  const auto found = object_.find(std::string(key));
  return found == object_.end() ? nullptr : &*found;
}

double JsonFields::Number(std::string_view key, double fallback) {
  const nlohmann::json* value = Find(key);
  if (value == nullptr) return fallback;
  if (!value->is_number()) FailType(PathOf(key), "a number", *value);
  return value->get<double>();
}

std::uint64_t JsonFields::Unsigned(std::string_view key, std::uint64_t fallback) {
  const nlohmann::json* value = Find(key);
  if (value == nullptr) return fallback;
  if (value->is_number_unsigned()) return value->get<std::uint64_t>();
  if (value->is_number_integer() && value->get<std::int64_t>() >= 0) return value->get<std::uint64_t>();
  FailType(PathOf(key), "an integer >= 0", *value);
}

int JsonFields::Integer(std::string_view key, int fallback) {
  const nlohmann::json* value = Find(key);
  if (value == nullptr) return fallback;
  if (!value->is_number_integer()) FailType(PathOf(key), "an integer", *value);
  if (value->is_number_unsigned()
          ? value->get<std::uint64_t>() > static_cast<std::uint64_t>(std::numeric_limits<int>::max())
          : (value->get<std::int64_t>() > std::numeric_limits<int>::max() ||
             value->get<std::int64_t>() < std::numeric_limits<int>::min())) {
    FailType(PathOf(key), "an integer that fits in 32 bits", *value);
  }
  return value->get<int>();
}

std::string JsonFields::Text(std::string_view key, const std::string& fallback) {
  const nlohmann::json* value = Find(key);
  if (value == nullptr) return fallback;
  if (!value->is_string()) FailType(PathOf(key), "a string", *value);
  return value->get<std::string>();
}

bool JsonFields::Bool(std::string_view key, bool fallback) {
  const nlohmann::json* value = Find(key);
  if (value == nullptr) return fallback;
  if (!value->is_boolean()) FailType(PathOf(key), "true or false", *value);
  return value->get<bool>();
}

const nlohmann::json* JsonFields::Object(std::string_view key) {
  const nlohmann::json* value = Find(key);
  if (value != nullptr && !value->is_object()) FailType(PathOf(key), "an object", *value);
  return value;
}

void JsonFields::Finish() const {
  for (const auto& [key, value] : object_.items()) {
    if (!read_.contains(key)) {
      std::string known;
      for (const std::string& name : read_) known += (known.empty() ? "" : ", ") + name;
      throw InputError(PathOf(key) + ": unknown option (known: " + known + ")");
    }
  }
}

void RequireNoiseField(const std::string& prefix, bool ok, const char* field, double value, const char* expected) {
  if (!ok) {
    throw InputError(prefix + field + " = " + std::to_string(value) + ", expected " + expected);
  }
}

}  // namespace slamsweep::evaluator::inline noise
