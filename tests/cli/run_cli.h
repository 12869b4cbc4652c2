#pragma once

#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

#include "cli/command.h"

namespace slamsweep::testing {

/// What one in-process run of the command line produced.
struct CliRun {
  int exit_code = 0;
  std::string out;
  std::string err;
};

inline CliRun RunCli(std::vector<std::string> args) {
  args.insert(args.begin(), "slamsweep");
  std::vector<const char*> argv;
  for (const std::string& arg : args) argv.push_back(arg.c_str());
  std::ostringstream out;
  std::ostringstream err;
  CliRun run;
  run.exit_code = cli::RunCommandLine(static_cast<int>(argv.size()), argv.data(), cli::Streams{out, err});
  run.out = out.str();
  run.err = err.str();
  return run;
}

}  // namespace slamsweep::testing
