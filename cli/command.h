#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
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
/// `eval map-compare` on the `eval` subcommand.
void RegisterEvalMapCompareCommand(CLI::App& eval, const Streams& streams);
/// `vectorize` on the top-level app.
void RegisterVectorizeCommand(CLI::App& app, const Streams& streams);

/// `run CONFIG`: a whole sweep. Sets `exit_code` (0 ok, 1 some run failed, 130 interrupted).
void RegisterRunCommand(CLI::App& app, const Streams& streams, int& exit_code);
/// `plan CONFIG`: the expanded matrix, nothing run.
void RegisterPlanCommand(CLI::App& app, const Streams& streams);
/// `merge DIR... -o DIR`.
void RegisterMergeCommand(CLI::App& app, const Streams& streams);
/// `worker RUN_DIR` (hidden): one run, as started by `run`'s executors. Sets `exit_code`.
void RegisterWorkerCommand(CLI::App& app, const Streams& streams, int& exit_code);
/// `history record|compare`: nightly history and regression detection. Sets `exit_code` (3 when
/// compare finds a regression).
void RegisterHistoryCommands(CLI::App& app, const Streams& streams, int& exit_code);
/// `algorithms [--json]`: the adapters, what is installed, licences and parameter defaults.
void RegisterAlgorithmsCommand(CLI::App& app, const Streams& streams);
/// `report RESULT_DIR [-o DIR]`.
void RegisterReportCommand(CLI::App& app, const Streams& streams);
/// `serve --data DIR`: the service (queue, shared worker pool, HTTP API, page). Sets `exit_code`.
void RegisterServeCommand(CLI::App& app, const Streams& streams, int& exit_code);
/// `submit CONFIG --server URL [--wait]`: a sweep through the service. Sets `exit_code` (like `run`).
void RegisterSubmitCommand(CLI::App& app, const Streams& streams, int& exit_code);

/// Writes RESULT_DIR/report and prints where its index is (run and merge call it at the end).
void WriteSweepReport(const std::filesystem::path& result_dir, const Streams& streams);

/// Parses argv and runs the chosen command, every command in this process (the tests' way; the
/// programs run their own commands and start helpers for the others: program.h). Returns the
/// process exit code:
/// 0 success, 2 bad usage or input (message on `err`);
/// run and worker set their own codes (1 failed runs, 130 interrupted).
int RunCommandLine(int argc, const char* const* argv, const Streams& streams);

}  // namespace slamsweep::cli
