#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>

namespace slamsweep::slam {

/// The command line every roster driver shares (slam/README.md, "Driver contract"):
///   slamsweep-slam-<name> --input FILE --output-dir DIR [--seed N] [--stages N] [key=value ...]
struct DriverArgs {
  /// A slamsweep program input: CARMEN log or MRPT rawlog (scans and odometry only).
  std::filesystem::path input;
  /// Where trajectory.tum, map.yaml (+ map.png) and stages/ are written; created when missing.
  std::filesystem::path output_dir;
  /// The run's seed; a randomised algorithm without one is seeded with 0 so a run is always repeatable.
  std::optional<std::uint64_t> seed;
  /// How many stage maps to write, evenly spread over the scans (0: none).
  int stages = 10;
  /// Algorithm parameters by their upstream names, as given (values parsed by Parameters).
  std::map<std::string, std::string> parameters;
};

/// Parses argv[1..]. Anything malformed (unknown option, missing value, a parameter without '=',
/// a repeated key, a non-numeric seed) is an evaluator::InputError naming the argument and what
/// was expected.
DriverArgs ParseDriverArgs(std::span<const char* const> arguments);

/// The usage text printed with --help and after a usage error.
std::string DriverUsage(std::string_view program);

}  // namespace slamsweep::slam
