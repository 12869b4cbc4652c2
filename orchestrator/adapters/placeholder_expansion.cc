#include "orchestrator/adapters/placeholder_expansion.h"

#include <vector>

#include "evaluator/core/input_error.h"
#include "orchestrator/adapters/mrpt_ini.h"
#include "orchestrator/config/placeholders.h"

namespace slamsweep::orchestrator::inline adapters {

namespace ev = slamsweep::evaluator;

namespace {

std::vector<std::string> ParameterNames(const nlohmann::json& parameters) {
  std::vector<std::string> names;
  if (parameters.is_object()) {
    for (const auto& [name, value] : parameters.items()) names.push_back(name);
  }
  return names;
}

}  // namespace

std::string ExpandPlaceholders(std::string_view text, const PlaceholderValues& values, const std::string& field) {
  try {
    std::string out;
    for (const TemplatePiece& piece : ParseTemplate(text)) {
      if (!piece.is_placeholder) {
        out += piece.text;
        continue;
      }
      CheckPlaceholderName(piece.text, ParameterNames(values.parameters));
      const std::string& name = piece.text;
      if (name == "input") {
        out += values.input;
      } else if (name == "input_dir") {
        out += values.input_dir;
      } else if (name == "output_dir") {
        out += values.output_dir;
      } else if (name == "seed") {
        out += values.seed;
      } else if (name == "seed32") {
        out += values.seed32;
      } else if (name == "iteration") {
        out += values.iteration;
      } else {
        // The value is one argument as it is: line breaks are harmless without a shell.
        const std::string parameter = name.substr(kParameterPlaceholderPrefix.size());
        const nlohmann::json& value = values.parameters.at(parameter);
        out += value.is_string() ? value.get<std::string>() : IniValueText(value, "{" + name + "}");
      }
    }
    return out;
  } catch (const ev::InputError& error) {
    throw ev::InputError(field + ": " + error.what());
  }
}

std::string InputExtension(std::string_view input_format) {
  if (input_format == "rawlog") return ".rawlog";
  if (input_format == "carmen") return ".log";
  if (input_format == "tum") return ".tum";
  if (input_format == "rosbag2") return "";  // a bag folder, named like the sequence
  throw ev::InputError("algorithm.command.input_format: expected rawlog, carmen, tum or rosbag2, got '" +
                       std::string(input_format) + "'");
}

}  // namespace slamsweep::orchestrator::inline adapters
