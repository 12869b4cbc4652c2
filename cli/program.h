#pragma once
// slamsweep is three programs built from the command files of this folder, so that a command loads
// only the libraries it needs (docs/programs-and-libraries.md):
//   slamsweep        the core: light commands (trajectory metrics, plan, algorithms); it starts
//                    the helpers for the other commands, passing the command line on unchanged;
//   slamsweep-maps   map commands: eval map, eval map-compare, vectorize (OpenCV, libpng);
//   slamsweep-sweep  sweeps and data: run, merge, report, history, data, worker, serve, submit
//                    (SQLite, the report, cpp-httplib, and the MRPT/ROS format modules when a rawlog
//                    or bag is read).
// Each program's commands are listed in one function (core_commands.cc, maps_commands.cc,
// sweep_commands.cc): a command moves between programs by moving its line there and in
// kHelperCommands (helper_commands.cc).
#include <span>
#include <string_view>

#include "cli/command.h"

namespace slamsweep::cli {

/// Where a program's registration list puts its commands.
class CommandLine {
 public:
  CommandLine(CLI::App& app, const Streams& streams, int& exit_code)
      : app(app), streams(streams), exit_code(exit_code) {}

  /// The `eval` subcommand, created on first use (a program may have none of its commands).
  CLI::App& Eval();

  CLI::App& app;
  const Streams& streams;
  /// For commands that set their own exit code (run, worker, history).
  int& exit_code;

 private:
  CLI::App* eval_ = nullptr;
};

using RegisterCommands = void (*)(CommandLine& line);

/// The registration list of each program.
void RegisterCoreCommands(CommandLine& line);
void RegisterMapsCommands(CommandLine& line);
void RegisterSweepCommands(CommandLine& line);

/// A command that a helper program runs: the core lists it in its help and, when it is chosen,
/// replaces itself (exec) with the helper, which gets the same command line.
struct HelperCommand {
  /// "" for a top-level command, else its parent ("eval").
  std::string_view parent;
  std::string_view name;
  std::string_view description;
  /// The helper's file name, found next to slamsweep (evaluator/core/installation.h).
  std::string_view program;
  bool hidden = false;
  /// glibc tunables the helper is started with (added to $GLIBC_TUNABLES), e.g. malloc on
  /// transparent huge pages for the map commands, whose large images then take 2 MB pages instead
  /// of thousands of 4 kB page faults.
  std::string_view glibc_tunables = {};
};

/// The commands of slamsweep-maps and slamsweep-sweep, as the core lists them.
std::span<const HelperCommand> HelperCommands();

/// For a process that does one large computation and exits (a map's metrics, one worker run):
/// memory it frees stays with it for its next allocations instead of going back to the kernel
/// and being faulted in, page by page, again. glibc's defaults return every freed block above
/// 128 KB and trim the heap top, which made OpenCV's per-band buffers cost 20 000 page faults on
/// a 2000 x 2000 map.
void ReuseFreedMemory();

/// Parses argv with the commands of `own` (in this order) in-process and `helpers` forwarded, and
/// runs the chosen one. Exit codes as RunCommandLine; a helper that cannot be found or started is
/// exit 1 with a message naming it and where it was looked for.
int RunProgram(int argc, const char* const* argv, const Streams& streams, std::span<const RegisterCommands> own,
               std::span<const HelperCommand> helpers);

}  // namespace slamsweep::cli
