#pragma once

#include <CLI/CLI.hpp>

#include <iosfwd>

namespace slamsweep::cli {

/// Where a command writes: results to `out` (stdout, one JSON object with --json),
/// diagnostics to `err`. Tests pass string streams.
struct Streams {
  std::ostream& out;
  std::ostream& err;
};

/// Each subcommand file registers itself on the parent CLI11 app; its callback throws
/// evaluator::InputError for bad input, which main maps to exit code 2.
/// `eval ape|rpe|relations` on the `eval` subcommand.
void RegisterEvalTrajectoryCommands(CLI::App& eval, const Streams& streams);
/// `eval map` on the `eval` subcommand.
void RegisterEvalMapCommand(CLI::App& eval, const Streams& streams);
/// `data info|convert|map|simulate` on the top-level app.
void RegisterDataCommands(CLI::App& app, const Streams& streams);
/// `vectorize` on the top-level app.
void RegisterVectorizeCommand(CLI::App& app, const Streams& streams);

/// Parses argv and runs the chosen command. Returns the process exit code:
/// 0 success, 2 bad usage or input (message on `err`).
int RunCommandLine(int argc, const char* const* argv, const Streams& streams);

}  // namespace slamsweep::cli
