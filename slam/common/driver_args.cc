#include "slam/common/driver_args.h"

#include <charconv>
#include <string_view>

#include "evaluator/core/input_error.h"

namespace slamsweep::slam {
namespace {

using evaluator::InputError;

template <typename Number>
Number ParseNumber(std::string_view text, std::string_view option) {
  Number value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    throw InputError(std::string(option) + ": expected a non-negative integer, got '" + std::string(text) + "'");
  }
  return value;
}

}  // namespace

DriverArgs ParseDriverArgs(std::span<const char* const> arguments) {
  DriverArgs args;
  bool have_input = false;
  bool have_output = false;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string_view argument = arguments[i];
    const auto value = [&]() -> std::string_view {
      if (i + 1 >= arguments.size()) throw InputError(std::string(argument) + ": expected a value after it");
      return arguments[++i];
    };
    if (argument == "--input") {
      args.input = value();
      have_input = true;
    } else if (argument == "--output-dir") {
      args.output_dir = value();
      have_output = true;
    } else if (argument == "--seed") {
      args.seed = ParseNumber<std::uint64_t>(value(), "--seed");
    } else if (argument == "--stages") {
      args.stages = ParseNumber<int>(value(), "--stages");
    } else if (argument.starts_with("--")) {
      throw InputError("unknown option '" + std::string(argument) +
                       "': expected --input, --output-dir, --seed, --stages or key=value");
    } else {
      const std::size_t equals = argument.find('=');
      if (equals == std::string_view::npos || equals == 0) {
        throw InputError("argument '" + std::string(argument) + "': expected a parameter as key=value");
      }
      const std::string key(argument.substr(0, equals));
      if (!args.parameters.emplace(key, std::string(argument.substr(equals + 1))).second) {
        throw InputError("parameter '" + key + "' given twice");
      }
    }
  }
  if (!have_input) throw InputError("--input FILE is required");
  if (!have_output) throw InputError("--output-dir DIR is required");
  return args;
}

std::string DriverUsage(std::string_view program) {
  return "usage: " + std::string(program) +
         " --input FILE --output-dir DIR [--seed N] [--stages N] [key=value ...]\n"
         "       " +
         std::string(program) +
         " --list-parameters\n"
         "  FILE: a CARMEN log or MRPT rawlog holding scans and odometry\n"
         "  DIR:  receives trajectory.tum (one pose per scan), map.yaml + map.png, stages/stage-*.yaml\n";
}

}  // namespace slamsweep::slam
