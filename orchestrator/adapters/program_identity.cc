#include "orchestrator/adapters/program_identity.h"

#include <string>

#include "evaluator/core/input_error.h"
#include "orchestrator/adapters/mrpt_settings.h"
#include "orchestrator/adapters/placeholder_expansion.h"
#include "orchestrator/adapters/roster.h"
#include "orchestrator/config/placeholders.h"
#include "orchestrator/config/program_path.h"

namespace slamsweep::orchestrator::inline adapters {

namespace ev = slamsweep::evaluator;
namespace fs = std::filesystem;

namespace {

/// A command's program and the absolute files among its fixed arguments; arguments with a run
/// placeholder ({input}, {output_dir}...) name files of the run, not of the program.
std::vector<fs::path> CommandProgramFiles(const AlgorithmSpec& algorithm) {
  if (!algorithm.command || algorithm.command->argv.empty()) return {};
  PlaceholderValues values;
  values.parameters = algorithm.parameters;
  std::vector<fs::path> files;
  const std::vector<std::string>& argv = algorithm.command->argv;
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string field = "algorithm.command.argv[" + std::to_string(i) + "]";
    bool has_run_placeholder = false;
    for (const TemplatePiece& piece : ParseTemplate(argv[i])) {
      has_run_placeholder = has_run_placeholder || (piece.is_placeholder && !piece.text.starts_with("param:"));
    }
    if (has_run_placeholder) continue;
    const std::string value = ExpandPlaceholders(argv[i], values, field);
    if (i == 0) {
      files.push_back(ResolveProgram(value, fs::current_path()));
      continue;
    }
    std::error_code error;
    if (fs::path(value).is_absolute() && fs::is_regular_file(value, error)) files.emplace_back(value);
  }
  return files;
}

Seeding CommandSeeding(const AlgorithmSpec& algorithm) {
  if (!algorithm.command) return Seeding::kUnseeded;
  for (const std::string& argument : algorithm.command->argv) {
    for (const TemplatePiece& piece : ParseTemplate(argument)) {
      if (piece.is_placeholder && (piece.text == "seed" || piece.text == "seed32")) return Seeding::kSeeded;
    }
  }
  return Seeding::kUnseeded;
}

}  // namespace

std::vector<fs::path> ProgramFilesOf(const AlgorithmSpec& algorithm) {
  const std::string& adapter = algorithm.adapter;
  // The MRPT programs are found in PATH; the .ini is rendered from Debian's template.
  if (adapter == "mrpt-icp-slam") return {ResolveProgram("icp-slam", fs::current_path()), kIcpSlamTemplate};
  if (adapter == "mrpt-rbpf-slam") return {ResolveProgram("rbpf-slam", fs::current_path()), kRbpfSlamTemplate};
  if (adapter == "command") return CommandProgramFiles(algorithm);
  if (adapter == "odometry") return {};
  if (const RosterAlgorithm* roster = FindRosterAlgorithm(adapter)) return RosterProgramFiles(*roster);
  ThrowUnknownAdapter(adapter);
}

Seeding SeedingOf(const AlgorithmSpec& algorithm) {
  const std::string& adapter = algorithm.adapter;
  if (adapter == "mrpt-icp-slam" || adapter == "odometry") return Seeding::kDeterministic;  // ICP draws nothing
  if (adapter == "mrpt-rbpf-slam") return Seeding::kSeeded;                                 // through RANDOM_SEED
  if (adapter == "command") return CommandSeeding(algorithm);
  if (const RosterAlgorithm* roster = FindRosterAlgorithm(adapter)) return roster->seeding;
  ThrowUnknownAdapter(adapter);
}

void ThrowUnknownAdapter(std::string_view name) {
  throw ev::InputError(
      "algorithm.adapter: expected mrpt-icp-slam, mrpt-rbpf-slam, command, odometry, gmapping, "
      "tinyslam, vinyslam, hector, cartographer, slam-toolbox, lama or lama-pf, got '" +
      std::string(name) + "'");
}

}  // namespace slamsweep::orchestrator::inline adapters
