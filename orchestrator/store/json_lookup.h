#pragma once

#include <nlohmann/json.hpp>

namespace slamsweep::orchestrator {

/// The value at `key` of a result or run file's object, or null when it is missing or `object` is no object.
inline const nlohmann::json& FieldOrNull(const nlohmann::json& object, const char* key) {
  static const nlohmann::json kNull;
  if (!object.is_object()) return kNull;
  const auto it = object.find(key);
  return it == object.end() ? kNull : *it;
}

/// object[outer][inner], null where either is missing.
inline const nlohmann::json& Nested(const nlohmann::json& object, const char* outer, const char* inner) {
  return FieldOrNull(FieldOrNull(object, outer), inner);
}

}  // namespace slamsweep::orchestrator
