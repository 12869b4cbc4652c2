#include "orchestrator/run/run_flags.h"

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator::inline run {
namespace {

using evaluator::InputError;
using nlohmann::json;

struct FlagText {
  RunFlag flag;
  std::string_view name;
  std::string_view label;
  std::string_view meaning;
};

constexpr FlagText kTexts[] = {
    {RunFlag::kOdometryIsReference, "odometry_is_reference", "odometry = reference",
     "an upper bound, not a SLAM result: the program was handed the reference trajectory as its odometry"},
    {RunFlag::kStale, "stale", "stale",
     "reused from an earlier sweep run under another build or evaluation (--reuse-stale): not comparable with "
     "this sweep's runs"},
    {RunFlag::kUnisolated, "unisolated", "unisolated",
     "the program ran outside the sandbox (--allow-unisolated): it could have read the reference or other runs"},
};

const FlagText& TextOf(RunFlag flag) {
  for (const FlagText& text : kTexts) {
    if (text.flag == flag) return text;
  }
  return kTexts[0];  // unreachable: every enumerator has a row
}

// Names joined by `separator` (appended piecewise: GCC 12 warns falsely on "" + std::string).
template <typename Range, typename Name>
std::string Joined(const Range& range, std::string_view separator, Name name) {
  std::string text;
  for (const auto& item : range) {
    if (!text.empty()) text += separator;
    text += name(item);
  }
  return text;
}

std::string KnownNames() {
  return Joined(kTexts, ", ", [](const FlagText& text) { return text.name; });
}

RunFlag Parse(std::string_view name, const std::string& where) {
  if (const std::optional<RunFlag> flag = RunFlagFromName(name)) return *flag;
  throw InputError(where + ": unknown run flag \"" + std::string(name) + "\" (known: " + KnownNames() + ")");
}

}  // namespace

std::string_view RunFlagName(RunFlag flag) { return TextOf(flag).name; }
std::string_view RunFlagLabel(RunFlag flag) { return TextOf(flag).label; }
std::string_view RunFlagMeaning(RunFlag flag) { return TextOf(flag).meaning; }

std::optional<RunFlag> RunFlagFromName(std::string_view name) {
  for (const FlagText& text : kTexts) {
    if (text.name == name) return text.flag;
  }
  return std::nullopt;
}

void RunFlags::Set(RunFlag flag, bool on) {
  if (on) {
    flags_.insert(flag);
  } else {
    flags_.erase(flag);
  }
}

RunFlags& RunFlags::operator|=(const RunFlags& other) {
  flags_.insert(other.flags_.begin(), other.flags_.end());
  return *this;
}

json ToJson(const RunFlags& flags) {
  json names = json::array();
  for (RunFlag flag : flags) names.push_back(RunFlagName(flag));
  return names;
}

RunFlags RunFlagsFromJson(const json& value, const std::string& path) {
  RunFlags flags;
  if (value.is_null()) return flags;
  if (!value.is_array()) throw InputError(path + ": expected an array of run flag names, got " + value.dump());
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string where = path + "[" + std::to_string(i) + "]";
    if (!value[i].is_string()) throw InputError(where + ": expected a run flag name, got " + value[i].dump());
    flags.Set(Parse(value[i].get<std::string>(), where));
  }
  return flags;
}

std::string RunFlagsText(const RunFlags& flags) { return Joined(flags, ";", RunFlagName); }

RunFlags RunFlagsFromText(std::string_view text, const std::string& what) {
  RunFlags flags;
  while (!text.empty()) {
    const std::size_t end = text.find(';');
    flags.Set(Parse(text.substr(0, end), what));
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return flags;
}

std::string RunFlagsLabel(const RunFlags& flags) { return Joined(flags, ", ", RunFlagLabel); }

RunFlags RunFlagsOf(const json& run_json, const json& result_json) {
  RunFlags flags;
  if (result_json.is_object()) {
    if (const auto it = result_json.find("flags"); it != result_json.end()) {
      flags = RunFlagsFromJson(*it, "result.json: flags");
    }
  }
  // Runs recorded before the flags field existed carry only the booleans.
  const auto boolean = [](const json& object, const char* key) -> std::optional<bool> {
    if (!object.is_object()) return std::nullopt;
    const auto it = object.find(key);
    if (it == object.end() || !it->is_boolean()) return std::nullopt;
    return it->get<bool>();
  };
  std::optional<bool> reference = boolean(result_json, "odometry_is_reference");
  if (!reference) reference = boolean(run_json, "odometry_is_reference");
  if (reference && *reference) flags.Set(RunFlag::kOdometryIsReference);
  return flags;
}

}  // namespace slamsweep::orchestrator::inline run
