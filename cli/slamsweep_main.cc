// The core program: light commands in-process, the others handed to a helper (cli/program.h).
#include <array>
#include <iostream>

#include "cli/program.h"

int main(int argc, char** argv) {
  using namespace slamsweep::cli;
  constexpr std::array<RegisterCommands, 1> kOwn = {RegisterCoreCommands};
  return RunProgram(argc, argv, Streams{std::cout, std::cerr}, kOwn, HelperCommands());
}
