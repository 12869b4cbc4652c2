#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace slamsweep::orchestrator::inline adapters {

/// One `key=value` line of an MRPT .ini file, in `[section]`.
struct IniSetting {
  std::string section;
  std::string key;
  std::string value;
  bool operator==(const IniSetting&) const = default;
};

/// The ini text of a scalar parameter: a string as it is, a bool as "true"/"false", a number in
/// its shortest JSON form. Other values, and text with a line break (it would smuggle extra lines
/// into the file), are InputErrors naming `field`.
std::string IniValueText(const nlohmann::json& value, const std::string& field);

/// Run parameters named "SECTION.key" (split at the first dot) as settings, in the parameters'
/// order. A name without a dot, or with an empty section or key, is an InputError naming
/// "algorithm.parameters.<name>" and the expected form.
std::vector<IniSetting> IniSettingsFromParameters(const nlohmann::json& parameters);

/// `template_text` with each setting applied: every `key = ...` line of the setting's section
/// (names compared case-insensitively, as MRPT's config reader does) becomes `key=value`; a key the
/// section lacks is added at the end of the section, and a missing section is appended. Later
/// settings win. Comment lines (#, ;, //) and all other lines are kept as they are.
std::string RenderIni(std::string_view template_text, std::span<const IniSetting> settings);

}  // namespace slamsweep::orchestrator::inline adapters
