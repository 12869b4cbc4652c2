// The commands of the core program, `slamsweep`: light ones, whose libraries load in a few
// milliseconds. A new light subcommand is one line here; heavy ones go to a helper (program.h).
#include "cli/program.h"

namespace slamsweep::cli {

void RegisterCoreCommands(CommandLine& line) {
  RegisterEvalTrajectoryCommands(line.Eval(), line.streams);
  RegisterPlanCommand(line.app, line.streams);
  RegisterAlgorithmsCommand(line.app, line.streams);
}

}  // namespace slamsweep::cli
