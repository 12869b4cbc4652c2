// Thin entry point: everything testable lives in RunCommandLine.
#include <iostream>

#include "cli/command.h"

int main(int argc, char** argv) {
  const slamsweep::cli::Streams streams{std::cout, std::cerr};
  return slamsweep::cli::RunCommandLine(argc, argv, streams);
}
