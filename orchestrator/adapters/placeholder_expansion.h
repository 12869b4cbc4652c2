#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace slamsweep::orchestrator::inline adapters {

/// What the placeholders of a command declaration stand for in one run.
struct PlaceholderValues {
  std::string input;       ///< {input}: the sequence file written for the program (absolute)
  std::string input_dir;   ///< {input_dir}: the folder of the input (the run's input/, absolute)
  std::string output_dir;  ///< {output_dir}: the run's raw/ folder (absolute), the program's working directory
  std::string seed;        ///< {seed}
  std::string seed32;      ///< {seed32}: Seed32(seed)
  std::string iteration;   ///< {iteration}
  nlohmann::json parameters = nlohmann::json::object();  ///< {param:NAME}
};

/// `text` with every placeholder (config/placeholders.h) replaced; "{{" and "}}" stand for literal
/// braces. An unknown placeholder, an unclosed brace or a parameter the run does not have is an
/// InputError naming `field` and what is accepted. The config checks templates with the same parser.
/// The result is one argument whatever it holds (spaces, ';', quotes): no shell ever sees it.
std::string ExpandPlaceholders(std::string_view text, const PlaceholderValues& values, const std::string& field);

/// The file extension of a written input format: "rawlog" -> ".rawlog", "carmen" -> ".log", "tum" -> ".tum".
std::string InputExtension(std::string_view input_format);

}  // namespace slamsweep::orchestrator::inline adapters
