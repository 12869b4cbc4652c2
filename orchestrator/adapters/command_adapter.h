#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "orchestrator/adapters/adapter.h"

namespace slamsweep::orchestrator {

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

/// A SLAM program run through its declared argv (run_spec.h CommandDeclaration). Prepare writes
/// input/<seq>.<ext> in input_format and expands the argv. Collect reads the declared trajectory
/// (on the sequence clock; MRPT paths are stamped by step = scan) and map; without a declared map
/// the map is rendered from the trajectory and the scans. Stage maps come from stage_maps_glob,
/// else they are rendered from the trajectory when there is one.
class CommandAdapter : public Adapter {
 public:
  PreparedRun Prepare(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
  CollectedOutputs Collect(const RunSpec& spec, const evaluator::RobotLog& robot, const RunPaths& paths) const override;
  /// The program (argv[0], its {param:...} expanded, found in PATH when it names no folder) and every
  /// other argument that is an absolute path to an existing file (a config file, a wrapper's script).
  std::vector<std::filesystem::path> ProgramFiles(const AlgorithmSpec& algorithm) const override;
  /// Seeded when an argument uses {seed} or {seed32}; unseeded otherwise (slamsweep cannot tell a
  /// deterministic program from one that seeds itself from the clock).
  Seeding SeedingOf(const AlgorithmSpec& algorithm) const override;
};

}  // namespace slamsweep::orchestrator
