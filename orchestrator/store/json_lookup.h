#pragma once

#include <nlohmann/json.hpp>

namespace slamsweep::orchestrator::inline store {

/// The value at `key` of a result or run file's object, or nullptr when it is missing or `object` is no object.
inline const nlohmann::json* FindField(const nlohmann::json& object, const char* key) {
  if (!object.is_object()) return nullptr;
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

/// FindField's value, or null.
inline const nlohmann::json& FieldOrNull(const nlohmann::json& object, const char* key) {
  static const nlohmann::json kNull;
  const nlohmann::json* found = FindField(object, key);
  return found != nullptr ? *found : kNull;
}

/// object[outer][inner], null where either is missing.
inline const nlohmann::json& Nested(const nlohmann::json& object, const char* outer, const char* inner) {
  return FieldOrNull(FieldOrNull(object, outer), inner);
}

}  // namespace slamsweep::orchestrator::inline store
