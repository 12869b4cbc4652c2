#include "cli/command.h"
#include "evaluator/core/input_error.h"

namespace slamsweep::cli {

int RunCommandLine(int argc, const char* const* argv, const Streams& streams) {
  CLI::App app{"slamsweep: batch benchmarking of 2D laser SLAM", "slamsweep"};
  app.require_subcommand(1);
  CLI::App* eval = app.add_subcommand("eval", "score one SLAM output (trajectory or map)");
  eval->require_subcommand(1);
  RegisterEvalTrajectoryCommands(*eval, streams);
  RegisterEvalMapCommand(*eval, streams);
  RegisterEvalMapCompareCommand(*eval, streams);
  RegisterVectorizeCommand(app, streams);
  RegisterDataCommands(app, streams);
  int exit_code = 0;
  RegisterPlanCommand(app, streams);
  RegisterRunCommand(app, streams, exit_code);
  RegisterMergeCommand(app, streams);
  RegisterReportCommand(app, streams);
  RegisterAlgorithmsCommand(app, streams);
  RegisterWorkerCommand(app, streams, exit_code);
  RegisterHistoryCommands(app, streams, exit_code);
  RegisterServeCommand(app, streams, exit_code);
  RegisterSubmitCommand(app, streams, exit_code);
  try {
    app.parse(argc, argv);
    return exit_code;
  } catch (const CLI::ParseError& error) {
    // CLI11 prints help (exit 0) or the usage error; any usage error exits 2, like bad input.
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
