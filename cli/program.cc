#include <malloc.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/program.h"
#include "evaluator/core/input_error.h"
#include "evaluator/core/installation.h"
#include "orchestrator/build_identity/revision.h"

namespace slamsweep::cli {
namespace {

bool HasSubcommand(CLI::App& parent, std::string_view name) {
  return !parent.get_subcommands([name](CLI::App* command) { return command->get_name() == name; }).empty();
}

/// This process's environment, with `tunables` appended to GLIBC_TUNABLES (read by glibc when the
/// helper starts; nothing the helper starts inherits it, as the map commands start nothing).
std::vector<std::string> HelperEnvironment(std::string_view tunables) {
  std::vector<std::string> environment;
  bool merged = tunables.empty();
  for (char** variable = environ; *variable != nullptr; ++variable) {
    std::string entry(*variable);
    if (!merged && entry.starts_with("GLIBC_TUNABLES=")) {
      entry += (entry.size() > std::string_view("GLIBC_TUNABLES=").size() ? ":" : "") + std::string(tunables);
      merged = true;
    }
    environment.push_back(std::move(entry));
  }
  if (!merged) environment.push_back("GLIBC_TUNABLES=" + std::string(tunables));
  return environment;
}

/// Replaces this process with the helper that runs `command`, giving it the same arguments.
[[noreturn]] void StartHelper(const HelperCommand& command, int argc, const char* const* argv, const Streams& streams) {
  const std::optional<std::filesystem::path> program = evaluator::FindLibexecFile(command.program);
  if (!program) {
    const std::string name =
        (command.parent.empty() ? "" : std::string(command.parent) + " ") + std::string(command.name);
    throw std::runtime_error("`" + name + "` needs the helper program " + std::string(command.program) +
                             ", which is missing; " + evaluator::DescribeLibexecSearch());
  }
  std::vector<char*> arguments;
  arguments.push_back(const_cast<char*>(program->c_str()));
  for (int i = 1; i < argc; ++i) arguments.push_back(const_cast<char*>(argv[i]));
  arguments.push_back(nullptr);
  const std::vector<std::string> environment = HelperEnvironment(command.glibc_tunables);
  std::vector<char*> variables;
  for (const std::string& variable : environment) variables.push_back(const_cast<char*>(variable.c_str()));
  variables.push_back(nullptr);
  streams.out.flush();
  streams.err.flush();
  ::execve(program->c_str(), arguments.data(), variables.data());
  throw std::runtime_error("cannot start the helper program " + program->string() + ": " + std::strerror(errno));
}

/// Lists a helper's command in this program's help and starts the helper when it is chosen. Its
/// arguments, --help included, are the helper's to read.
void AddHelperCommand(CommandLine& line, const HelperCommand& command, int argc, const char* const* argv) {
  CLI::App& parent = command.parent.empty() ? line.app : line.Eval();
  if (HasSubcommand(parent, command.name)) return;  // this program runs it itself
  CLI::App* stub = parent.add_subcommand(std::string(command.name), std::string(command.description));
  stub->prefix_command();
  stub->allow_extras();
  stub->set_help_flag();
  if (command.hidden) stub->group("");
  const Streams& streams = line.streams;
  stub->callback([&command, argc, argv, &streams] { StartHelper(command, argc, argv, streams); });
}

}  // namespace

void ReuseFreedMemory() {
  // Blocks up to 32 MB come from the heap, and up to 256 MB of free heap top is kept.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  // One arena for every thread: a helper thread (the map metrics' second core) reuses the memory the
  // main thread has already touched instead of faulting in an arena of its own.
  mallopt(M_ARENA_MAX, 1);
}

CLI::App& CommandLine::Eval() {
  if (eval_ == nullptr) {
    eval_ = app.add_subcommand("eval", "score one SLAM output (trajectory or map)");
    eval_->require_subcommand(1);
  }
  return *eval_;
}

int RunProgram(int argc, const char* const* argv, const Streams& streams, std::span<const RegisterCommands> own,
               std::span<const HelperCommand> helpers) {
  CLI::App app{"slamsweep: batch benchmarking of 2D laser SLAM", "slamsweep"};
  app.require_subcommand(1);
  app.footer(
      "The manual is docs/ of the slamsweep sources, arranged by task (docs/README.md): getting started, sweep "
      "files, data, metrics, the report, the roster, the service, Jenkins.");
  app.set_version_flag("--version", "slamsweep " + std::string(orchestrator::SlamsweepRevision()));
  int exit_code = 0;
  CommandLine line(app, streams, exit_code);
  for (RegisterCommands register_commands : own) register_commands(line);
  for (const HelperCommand& command : helpers) AddHelperCommand(line, command, argc, argv);
  try {
    app.parse(argc, argv);
    return exit_code;
  } catch (const CLI::ParseError& error) {
    // CLI11 prints help or the version (exit 0) or the usage error; any usage error exits 2, like bad input.
    const int code = app.exit(error, streams.out, streams.err);
    return code == 0 ? 0 : 2;
  } catch (const evaluator::InputError& error) {
    streams.err << "slamsweep: error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    // Not the user's fault: say so, and keep exit 2 reserved for input problems.
    streams.err << "slamsweep: internal error: " << error.what() << "\n";
    return 1;
  }
}

}  // namespace slamsweep::cli
