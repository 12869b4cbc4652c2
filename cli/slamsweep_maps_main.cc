// slamsweep-maps: the map commands, started by `slamsweep` (cli/program.h).
#include <array>
#include <iostream>

#include "cli/program.h"

int main(int argc, char** argv) {
  using namespace slamsweep::cli;
  constexpr std::array<RegisterCommands, 1> kOwn = {RegisterMapsCommands};
  ReuseFreedMemory();  // every command here scores or converts one map, then exits
  return RunProgram(argc, argv, Streams{std::cout, std::cerr}, kOwn, {});
}
