#include "orchestrator/config/algorithm_config.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string_view>

#include "evaluator/core/input_error.h"
#include "orchestrator/run/spec_checks.h"
#include "orchestrator/config/placeholders.h"
#include "orchestrator/config/program_path.h"
#include "orchestrator/config/yaml_fields.h"

namespace slamsweep::orchestrator::inline config {
namespace {

constexpr std::string_view kAdapters[] = {"mrpt-icp-slam", "mrpt-rbpf-slam", "command",  "odometry",
                                          "gmapping",      "tinyslam",       "vinyslam", "hector",
                                          "cartographer",  "slam-toolbox",   "lama",     "lama-pf"};
constexpr std::string_view kInputFormats[] = {"rawlog", "carmen", "tum", "rosbag2"};
constexpr std::string_view kTrajectoryFormats[] = {"tum", "kitti", "csv", "mrpt", "carmen"};
constexpr std::string_view kMapFormats[] = {"map_server", "mrpt", "pgm"};

nlohmann::json ParameterValue(const std::filesystem::path& file, const YAML::Node& node, const std::string& path) {
  if (!node.IsScalar()) FailExpected(file, node, path, "a number, text or true/false");
  return YamlToJson(node);
}

std::vector<ParameterAxis> ParseParameters(const std::filesystem::path& file, const YAML::Node& node,
                                           const std::string& path) {
  std::vector<ParameterAxis> axes;
  if (!node.IsDefined() || node.IsNull()) return axes;
  if (!node.IsMap()) FailExpected(file, node, path, "a map of parameter names to values or lists of values");
  for (const auto& item : node) {
    ParameterAxis axis;
    axis.name = item.first.Scalar();
    const std::string value_path = path + "." + axis.name;
    if (axis.name.empty()) FailExpected(file, item.first, path, "non-empty parameter names");
    if (item.second.IsSequence()) {
      if (item.second.size() == 0) FailExpected(file, item.second, value_path, "at least one value to sweep");
      for (const auto& value : item.second) axis.values.push_back(ParameterValue(file, value, value_path));
      for (std::size_t i = 0; i < axis.values.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
          if (axis.values[i] == axis.values[j]) {
            FailAt(file, item.second[i],
                   fmt::format("{}: value {} is listed twice (it would run the same cell twice)", value_path,
                               axis.values[i].dump()));
          }
        }
      }
    } else {
      axis.values.push_back(ParameterValue(file, item.second, value_path));
    }
    axes.push_back(std::move(axis));
  }
  return axes;
}

/// Checks every {...} of `text` against the known placeholders and declared parameters, with the
/// same parser the adapter expands them with (so "{{" and "}}" mean the same to both).
void CheckPlaceholders(const std::filesystem::path& file, const YAML::Node& node, const std::string& path,
                       const std::string& text, const std::set<std::string, std::less<>>& parameters) {
  const std::vector<std::string> declared(parameters.begin(), parameters.end());
  try {
    for (const TemplatePiece& piece : ParseTemplate(text)) {
      if (piece.is_placeholder) CheckPlaceholderName(piece.text, declared);
    }
  } catch (const evaluator::InputError& error) {
    FailAt(file, node, fmt::format("{}: {}", path, error.what()));
  }
}

/// The program of a command, checked now rather than in every run: found (in PATH when it names no
/// folder) and executable. A path with a folder is taken relative to the sweep file's folder and
/// made absolute, so that it means the same wherever the worker runs it; a bare name stays as
/// written (the run id must not depend on where a machine's PATH finds it; the build identity
/// records the file's digest). A program chosen by a placeholder ({param:binary}) is checked when it runs.
void CheckProgram(const std::filesystem::path& file, const YAML::Node& node, const std::string& path,
                  std::string& program) {
  if (program.find('{') != std::string::npos) return;
  try {
    const std::filesystem::path resolved = ResolveProgram(program, file.parent_path());
    if (program.find('/') != std::string::npos) program = resolved.string();
  } catch (const evaluator::InputError& error) {
    FailAt(file, node, fmt::format("{}: {}", path, error.what()));
  }
}

template <std::size_t N>
std::optional<DeclaredOutput> ParseDeclaredOutput(const std::filesystem::path& file, const YAML::Node& node,
                                                  const std::string& path, const std::string_view (&formats)[N],
                                                  const std::set<std::string, std::less<>>& parameters) {
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  YamlFields fields(file, node, path);
  DeclaredOutput output;
  output.path = fields.RequiredText("path");
  CheckPlaceholders(file, fields.Get("path"), fields.PathOf("path"), output.path, parameters);
  output.format = fields.RequiredText("format");
  if (!OneOf(output.format, formats))
    FailExpected(file, fields.Get("format"), fields.PathOf("format"), Choices(formats));
  fields.Finish();
  return output;
}

/// `command.read_only`: folders and files, relative to the sweep file's folder or absolute, that
/// exist and that the policy lets the file name; absolute and normalised in the run.
std::vector<std::string> ParseReadOnly(const std::filesystem::path& file, const YAML::Node& node,
                                       const std::string& path, const InputPolicy& policy) {
  std::vector<std::string> paths;
  if (!node.IsDefined() || node.IsNull()) return paths;
  if (!node.IsSequence()) FailExpected(file, node, path, "a list of folders and files the program reads");
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string item_path = fmt::format("{}[{}]", path, i);
    if (!node[i].IsScalar() || node[i].Scalar().empty()) FailExpected(file, node[i], item_path, "a path");
    const std::filesystem::path resolved = (file.parent_path() / node[i].Scalar()).lexically_normal();
    RequireAllowedPath(policy, file, node[i], item_path, "folder the program reads", resolved);
    std::error_code error;
    if (!std::filesystem::exists(resolved, error)) {
      FailAt(file, node[i], fmt::format("{}: {} does not exist", item_path, resolved.string()));
    }
    if (resolved == resolved.root_path()) FailExpected(file, node[i], item_path, "a folder other than /");
    paths.push_back(std::filesystem::absolute(resolved).lexically_normal().string());
  }
  return paths;
}

CommandDeclaration ParseCommand(const std::filesystem::path& file, const YAML::Node& node, const std::string& path,
                                const std::set<std::string, std::less<>>& parameters, const InputPolicy& policy) {
  YamlFields fields(file, node, path);
  CommandDeclaration command;
  const YAML::Node argv = fields.Get("argv");
  if (!argv.IsDefined())
    FailAt(file, node, fmt::format("{}: missing (required: the program and its arguments)", fields.PathOf("argv")));
  if (!argv.IsSequence() || argv.size() == 0) {
    FailExpected(file, argv, fields.PathOf("argv"), "a non-empty list: the program, then one item per argument");
  }
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string item_path = fmt::format("{}[{}]", fields.PathOf("argv"), i);
    if (!argv[i].IsScalar()) FailExpected(file, argv[i], item_path, "a text value");
    command.argv.push_back(argv[i].Scalar());
    CheckPlaceholders(file, argv[i], item_path, command.argv.back(), parameters);
  }
  if (command.argv.front().empty()) FailExpected(file, argv[0], fields.PathOf("argv") + "[0]", "a program name");
  CheckProgram(file, argv[0], fields.PathOf("argv") + "[0]", command.argv.front());
  command.input_format = fields.Text("input_format", command.input_format);
  if (!OneOf(command.input_format, kInputFormats)) {
    FailExpected(file, fields.Get("input_format"), fields.PathOf("input_format"), Choices(kInputFormats));
  }
  command.trajectory =
      ParseDeclaredOutput(file, fields.Get("trajectory"), fields.PathOf("trajectory"), kTrajectoryFormats, parameters);
  command.map = ParseDeclaredOutput(file, fields.Get("map"), fields.PathOf("map"), kMapFormats, parameters);
  command.stage_maps_glob = fields.Text("stage_maps", "");
  const std::uint64_t unknown = fields.Unsigned("stage_unknown_value", 205);
  if (unknown > 255)
    FailExpected(file, fields.Get("stage_unknown_value"), fields.PathOf("stage_unknown_value"), "a grey level 0..255");
  command.stage_unknown_value = static_cast<int>(unknown);
  command.read_only = ParseReadOnly(file, fields.Get("read_only"), fields.PathOf("read_only"), policy);
  fields.Finish();
  if (!command.trajectory && !command.map) {
    FailAt(file, node, fmt::format("{}: expected a trajectory or a map output to score, got neither", path));
  }
  return command;
}

}  // namespace

AlgorithmConfig ParseAlgorithmConfig(const std::filesystem::path& file, const YAML::Node& node, const std::string& path,
                                     const InputPolicy& policy) {
  YamlFields fields(file, node, path);
  AlgorithmConfig algorithm;
  algorithm.name = fields.RequiredText("name");
  algorithm.adapter = fields.RequiredText("adapter");
  if (!OneOf(algorithm.adapter, kAdapters)) {
    FailExpected(file, fields.Get("adapter"), fields.PathOf("adapter"), Choices(kAdapters));
  }
  if (algorithm.adapter == "command" && !policy.allow_commands) {
    // Before the command is looked at: its program is not even searched for.
    throw PolicyError(LocatedAt(file, fields.Get("adapter"),
                                fmt::format("{}: the command adapter runs any program and this server does not allow "
                                            "it (start it with --allow-commands), got adapter: command",
                                            fields.PathOf("adapter"))));
  }
  algorithm.timeout_s = fields.Number("timeout_s", algorithm.timeout_s);
  if (!(algorithm.timeout_s > 0.0)) {
    FailExpected(file, fields.Get("timeout_s"), fields.PathOf("timeout_s"), "a number of seconds > 0");
  }
  algorithm.memory_limit_mb = fields.Unsigned("memory_limit_mb", algorithm.memory_limit_mb);
  algorithm.disk_limit_mb = fields.Unsigned("disk_limit_mb", algorithm.disk_limit_mb);
  if (algorithm.disk_limit_mb == 0)
    FailExpected(file, fields.Get("disk_limit_mb"), fields.PathOf("disk_limit_mb"), "a number of MB >= 1");
  algorithm.process_limit = fields.Unsigned("process_limit", algorithm.process_limit);
  if (algorithm.process_limit < kMinProcessLimit) {
    FailExpected(file, fields.Get("process_limit"), fields.PathOf("process_limit"),
                 fmt::format("a number of processes and threads >= {}", kMinProcessLimit));
  }
  algorithm.network = fields.Bool("network", algorithm.network);
  if (algorithm.network && !policy.allow_network) {
    throw PolicyError(
        LocatedAt(file, fields.Get("network"),
                  fmt::format("{}: this server gives programs no network (start it with --allow-network), "
                              "got network: true",
                              fields.PathOf("network"))));
  }
  if (fields.Has("iterations")) {
    const std::uint64_t iterations = fields.Unsigned("iterations", 1);
    if (iterations < 1 || iterations > 1000000) {
      FailExpected(file, fields.Get("iterations"), fields.PathOf("iterations"), "a whole number from 1 to 1000000");
    }
    algorithm.iterations = static_cast<int>(iterations);
  }
  algorithm.parameters = ParseParameters(file, fields.Get("parameters"), fields.PathOf("parameters"));
  std::set<std::string, std::less<>> declared;
  for (const ParameterAxis& axis : algorithm.parameters) declared.insert(axis.name);
  const YAML::Node command = fields.Get("command");
  if (algorithm.adapter == "command") {
    if (!command.IsDefined()) {
      FailAt(file, node,
             fmt::format("{}: missing (the command adapter needs argv and outputs)", fields.PathOf("command")));
    }
    algorithm.command = ParseCommand(file, command, fields.PathOf("command"), declared, policy);
  } else if (command.IsDefined()) {
    FailAt(file, command,
           fmt::format("{}: only the command adapter takes a command (adapter is {})", fields.PathOf("command"),
                       algorithm.adapter));
  }
  fields.Finish();
  return algorithm;
}

}  // namespace slamsweep::orchestrator::inline config
