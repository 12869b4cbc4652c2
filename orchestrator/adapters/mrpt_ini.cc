#include "orchestrator/adapters/mrpt_ini.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <optional>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator::inline adapters {

namespace {

using evaluator::InputError;

std::string_view Trim(std::string_view text) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return text;
}

bool SameName(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

bool IsComment(std::string_view line) {
  return line.empty() || line.front() == '#' || line.front() == ';' || line.starts_with("//");
}

/// "[name]" -> name.
std::optional<std::string_view> SectionName(std::string_view line) {
  if (line.size() < 2 || line.front() != '[') return std::nullopt;
  const std::size_t close = line.find(']');
  if (close == std::string_view::npos) return std::nullopt;
  return Trim(line.substr(1, close - 1));
}

/// The key of a "key = value" line, or nothing.
std::optional<std::string_view> KeyOf(std::string_view line) {
  const std::size_t equals = line.find('=');
  if (equals == std::string_view::npos) return std::nullopt;
  const std::string_view key = Trim(line.substr(0, equals));
  if (key.empty()) return std::nullopt;
  return key;
}

struct Line {
  std::string text;
  std::string section;  // the section the line belongs to ("" before the first header)
};

}  // namespace

std::string IniValueText(const nlohmann::json& value, const std::string& field) {
  std::string text;
  if (value.is_string()) {
    text = value.get<std::string>();
  } else if (value.is_boolean()) {
    text = value.get<bool>() ? "true" : "false";
  } else if (value.is_number()) {
    text = value.dump();
  } else {
    throw InputError(field + ": expected a number, string or bool, got " + value.dump());
  }
  if (text.find_first_of("\r\n") != std::string::npos) {
    throw InputError(field + ": a value must be one line, got " + value.dump());
  }
  return text;
}

std::vector<IniSetting> IniSettingsFromParameters(const nlohmann::json& parameters) {
  if (!parameters.is_object()) throw InputError("algorithm.parameters: expected an object, got " + parameters.dump());
  std::vector<IniSetting> settings;
  for (const auto& [name, value] : parameters.items()) {
    const std::string field = "algorithm.parameters." + name;
    const std::size_t dot = name.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == name.size()) {
      throw InputError(field + ": expected a name SECTION.key (e.g. MappingApplication.insertionLinDistance)");
    }
    const std::string section = name.substr(0, dot);
    const std::string key = name.substr(dot + 1);
    if (section.find_first_of("[]\r\n") != std::string::npos || key.find_first_of("=\r\n") != std::string::npos) {
      throw InputError(field + ": a section cannot hold '[', ']' or line breaks, a key neither '=' nor line breaks");
    }
    settings.push_back({section, key, IniValueText(value, field)});
  }
  return settings;
}

std::string RenderIni(std::string_view template_text, std::span<const IniSetting> settings) {
  std::vector<Line> lines;
  std::string section;
  for (std::size_t start = 0; start < template_text.size();) {
    std::size_t end = template_text.find('\n', start);
    if (end == std::string_view::npos) end = template_text.size();
    const std::string_view text = template_text.substr(start, end - start);
    if (const auto name = SectionName(Trim(text))) section = std::string(*name);
    lines.push_back({std::string(text), section});
    start = end + 1;
  }

  for (const IniSetting& setting : settings) {
    const std::string replacement = setting.key + "=" + setting.value;
    bool replaced = false;
    std::optional<std::size_t> last_of_section;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (!SameName(lines[i].section, setting.section)) continue;
      const std::string_view trimmed = Trim(lines[i].text);
      if (!trimmed.empty()) last_of_section = i;
      if (IsComment(trimmed) || SectionName(trimmed)) continue;
      const auto key = KeyOf(trimmed);
      if (key && SameName(*key, setting.key)) {
        lines[i].text = replacement;
        replaced = true;
      }
    }
    if (replaced) continue;
    if (last_of_section) {
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(*last_of_section) + 1, {replacement, setting.section});
    } else {
      lines.push_back({"", ""});
      lines.push_back({"[" + setting.section + "]", setting.section});
      lines.push_back({replacement, setting.section});
    }
  }

  std::string out;
  for (const Line& line : lines) out += line.text + "\n";
  return out;
}

}  // namespace slamsweep::orchestrator::inline adapters
