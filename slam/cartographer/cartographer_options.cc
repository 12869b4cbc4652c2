#include "slam/cartographer/cartographer_options.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include <cartographer/common/configuration_file_resolver.h>
#include <cartographer/common/lua_parameter_dictionary.h>
#include <cartographer/mapping/map_builder_interface.h>
#include <cartographer/mapping/trajectory_builder_interface.h>

#include "evaluator/core/input_error.h"
#include "evaluator/core/installation.h"
#include "evaluator/core/installation.h"

namespace slamsweep::slam::cartographer_driver {
namespace {

namespace carto = ::cartographer;

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw evaluator::InputError(path + " missing: the Cartographer driver's Lua options");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// An installed driver's copy (PREFIX/share/slamsweep/cartographer/<name>), else the one this build used.
std::string OptionsPath(std::string_view name, const std::string& build_path) {
  const auto installed = evaluator::FindInstalledData("cartographer/" + std::string(name));
  return installed ? installed->string() : build_path;
}

/// Whether `path` (a.b.c) names an option of `options`: every step must exist. Checked on a
/// dictionary that does not count key uses, so the real one still sees each key exactly once.
bool HasPath(carto::common::LuaParameterDictionary& options, const std::string& path) {
  std::istringstream steps(path);
  std::vector<std::string> keys;
  for (std::string key; std::getline(steps, key, '.');) keys.push_back(key);
  if (keys.empty()) return false;
  std::unique_ptr<carto::common::LuaParameterDictionary> owned;
  carto::common::LuaParameterDictionary* dictionary = &options;
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    if (!dictionary->HasKey(keys[i])) return false;
    owned = dictionary->GetDictionary(keys[i]);
    dictionary = owned.get();
  }
  return dictionary->HasKey(keys.back());
}

/// A Lua literal for a parameter value: numbers and true/false as they are, anything else quoted.
std::string LuaLiteral(const std::string& value) {
  if (value == "true" || value == "false") return value;
  char* end = nullptr;
  std::strtod(value.c_str(), &end);
  if (!value.empty() && end == value.c_str() + value.size()) return value;
  std::string quoted = "\"";
  for (const char c : value) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

/// The options most often tuned, shown with their values by --list-parameters (any other path is
/// accepted too).
struct Listed {
  const char* path;
  enum { kDouble, kInt, kBool } type;
};
constexpr Listed kListed[] = {
    {"trajectory_builder.trajectory_builder_2d.min_range", Listed::kDouble},
    {"trajectory_builder.trajectory_builder_2d.max_range", Listed::kDouble},
    {"trajectory_builder.trajectory_builder_2d.missing_data_ray_length", Listed::kDouble},
    {"trajectory_builder.trajectory_builder_2d.use_online_correlative_scan_matching", Listed::kBool},
    {"trajectory_builder.trajectory_builder_2d.submaps.num_range_data", Listed::kInt},
    {"map_builder.pose_graph.optimize_every_n_nodes", Listed::kInt},
    {"map_builder.pose_graph.constraint_builder.min_score", Listed::kDouble},
    {"map_builder.pose_graph.constraint_builder.sampling_ratio", Listed::kDouble},
};

std::string ValueAt(carto::common::LuaParameterDictionary& options, const Listed& listed) {
  std::istringstream steps(listed.path);
  std::vector<std::string> keys;
  for (std::string key; std::getline(steps, key, '.');) keys.push_back(key);
  std::unique_ptr<carto::common::LuaParameterDictionary> owned;
  carto::common::LuaParameterDictionary* dictionary = &options;
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    owned = dictionary->GetDictionary(keys[i]);
    dictionary = owned.get();
  }
  switch (listed.type) {
    case Listed::kDouble: {
      std::ostringstream text;
      text << dictionary->GetDouble(keys.back());
      return text.str();
    }
    case Listed::kInt:
      return std::to_string(dictionary->GetInt(keys.back()));
    case Listed::kBool:
      return dictionary->GetBool(keys.back()) ? "true" : "false";
  }
  return "";
}

}  // namespace

CartographerOptions ReadCartographerOptions(Parameters& parameters) {
  // Beside the program (the build and the installation put slamsweep_2d.lua there): a file a run reads as
  // configuration sits where slamsweep's build identity finds and hashes it (orchestrator/adapters/roster.h).
  const std::filesystem::path self = evaluator::RunningProgram();
  if (self.empty())
    throw evaluator::InputError("cannot find the Cartographer driver's own folder (no /proc/self/exe, no AT_EXECFN)");
  const std::string base = ReadFile((self.parent_path() / "slamsweep-slam-cartographer.lua").string());
  const std::string upstream_files = OptionsPath("configuration_files", CARTOGRAPHER_CONFIGURATION_FILES);
  auto resolver = [&upstream_files] {
    return std::make_unique<carto::common::ConfigurationFileResolver>(std::vector<std::string>{upstream_files});
  };
  auto plain = carto::common::LuaParameterDictionary::NonReferenceCounted(base + "\nreturn options\n", resolver());
  for (const Listed& listed : kListed) {
    auto fresh = carto::common::LuaParameterDictionary::NonReferenceCounted(base + "\nreturn options\n", resolver());
    parameters.Text(listed.path, ValueAt(*fresh, listed));
  }
  std::string overrides;
  for (const std::string& key : parameters.GivenKeys()) {
    if (!HasPath(*plain, key)) {
      throw evaluator::InputError("parameter " + key +
                                  ": not an option of Cartographer's options table "
                                  "(e.g. trajectory_builder.trajectory_builder_2d.max_range)");
    }
    overrides += "options." + key + " = " + LuaLiteral(parameters.Text(key, "")) + "\n";
  }
  auto dictionary =
      carto::common::LuaParameterDictionary::NonReferenceCounted(base + overrides + "return options\n", resolver());
  CartographerOptions options;
  options.map_builder = carto::mapping::CreateMapBuilderOptions(dictionary->GetDictionary("map_builder").get());
  options.trajectory_builder =
      carto::mapping::CreateTrajectoryBuilderOptions(dictionary->GetDictionary("trajectory_builder").get());
  return options;
}

}  // namespace slamsweep::slam::cartographer_driver
