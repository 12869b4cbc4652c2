// `slamsweep algorithms [--json]`: every adapter a sweep can name, whether it is installed, its
// version or commit, its licence and its parameters with defaults.
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include "cli/command.h"
#include "orchestrator/adapters/algorithm_info.h"

namespace slamsweep::cli {

namespace {

nlohmann::json ToJson(const orchestrator::AlgorithmInfo& info) {
  nlohmann::json parameters = nlohmann::json::object();
  for (const auto& [key, value] : info.parameters) parameters[key] = value;
  return {{"adapter", info.adapter},
          {"title", info.title},
          {"installed", info.installed},
          {"status", info.status},
          {"license", info.license},
          {"seeding", info.seeding},
          {"parameters", parameters},
          {"parameter_note", info.parameter_note},
          {"defaults_note", info.defaults_note}};
}

void PrintText(const orchestrator::AlgorithmInfo& info, std::ostream& out) {
  out << info.adapter << (info.installed ? "  [installed]  " : "  [missing]  ") << info.title << "\n"
      << "  " << info.status << "\n"
      << "  licence: " << info.license << "; seeding: " << info.seeding << "\n"
      << "  parameters (" << info.parameter_note << ")" << (info.parameters.empty() ? "" : ":") << "\n";
  for (const auto& [key, value] : info.parameters) out << "    " << key << " = " << value << "\n";
  if (!info.defaults_note.empty()) out << "  defaults: " << info.defaults_note << "\n";
}

}  // namespace

void RegisterAlgorithmsCommand(CLI::App& app, const Streams& streams) {
  auto json = std::make_shared<bool>(false);
  CLI::App* command = app.add_subcommand("algorithms", "list every adapter: installed?, version, licence, parameters");
  command->add_flag("--json", *json, "print one JSON array");
  command->callback([json, streams] {
    const std::vector<orchestrator::AlgorithmInfo> all = orchestrator::DescribeAlgorithms();
    if (*json) {
      nlohmann::json list = nlohmann::json::array();
      for (const auto& info : all) list.push_back(ToJson(info));
      streams.out << list.dump(2) << "\n";
      return;
    }
    for (const auto& info : all) PrintText(info, streams.out);
  });
}

}  // namespace slamsweep::cli
