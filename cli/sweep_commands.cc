// The commands of `slamsweep-sweep`: sweeps, their results and report, sequence data, and the service
// and its client (SQLite, the report's libraries, cpp-httplib; MRPT and ROS as format modules when a
// rawlog or bag is read).
#include "cli/program.h"

namespace slamsweep::cli {

void RegisterSweepCommands(CommandLine& line) {
  RegisterDataCommands(line.app, line.streams);
  RegisterRunCommand(line.app, line.streams, line.exit_code);
  RegisterMergeCommand(line.app, line.streams);
  RegisterReportCommand(line.app, line.streams);
  RegisterWorkerCommand(line.app, line.streams, line.exit_code);
  RegisterHistoryCommands(line.app, line.streams, line.exit_code);
  RegisterServeCommand(line.app, line.streams, line.exit_code);
  RegisterSubmitCommand(line.app, line.streams, line.exit_code);
}

}  // namespace slamsweep::cli
