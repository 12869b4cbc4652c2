// Every command of every program in one process: what the tests run (cli/program.h has the programs).
#include <array>

#include "cli/program.h"

namespace slamsweep::cli {

int RunCommandLine(int argc, const char* const* argv, const Streams& streams) {
  constexpr std::array<RegisterCommands, 3> kEveryCommand = {RegisterCoreCommands, RegisterMapsCommands,
                                                             RegisterSweepCommands};
  return RunProgram(argc, argv, streams, kEveryCommand, {});
}

}  // namespace slamsweep::cli
