#pragma once

#include <string>
#include <vector>

#include "orchestrator/process/spawn.h"

namespace slamsweep::orchestrator::inline process {

/// How a program run by RunToExit ended.
struct ExitStatus {
  /// Empty when the program started; else why it could not (SpawnChild's detail: "No such file or directory").
  std::string start_error;
  /// The program's exit status, or 128 + signal number when a signal ended it.
  int exit_code = 0;
};

/// Starts `argv` as SpawnChild does (no shell, its own process group, the runner's environment) with
/// `streams`, and blocks until it ends. For short helper programs whose caller waits anyway (gnuplot):
/// no timeout, no limits, no interruption handling, no log. `streams` must send stdout and stderr
/// elsewhere (files, not pipes this thread would have to read), else std::invalid_argument.
/// Throws std::system_error when the wait fails (other code in this process reaped the child).
ExitStatus RunToExit(const std::vector<std::string>& argv, const ChildStreams& streams);

}  // namespace slamsweep::orchestrator::inline process
