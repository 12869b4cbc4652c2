#pragma once

#include <string>

#include <sys/types.h>

#include "orchestrator/process/process_spec.h"

namespace slamsweep::orchestrator {

/// A started child, or why it could not start.
struct SpawnResult {
  pid_t pid = -1;
  /// Read end of the pipe that carries the child's stdout and stderr (non-blocking, close-on-exec).
  int output_fd = -1;
  /// Read end of the sandbox's status pipe (close-on-exec, blocking), -1 when not sandboxed: the
  /// status lines of slamsweep-sandbox-init (orchestrator/sandbox), complete once the child ended.
  int status_fd = -1;
  /// Empty on success; else the detail of the failure ("No such file or directory").
  std::string error;
};

/// Starts `spec.argv` (Boost.Process) in its own process group (pgid = pid) with stdin from
/// /dev/null, stdout+stderr into one pipe, default signal dispositions, an empty signal mask, and
/// PR_SET_PDEATHSIG(SIGTERM) so a supervisor that dies does not leave programs behind. Note that the
/// kernel sends that signal when the spawning THREAD ends, so spawn from a long-lived thread.
/// With spec.sandbox, the child is bubblewrap running the program in that sandbox.
/// Never throws for a program that cannot start. The caller owns the pid (reaps it) and the fds.
SpawnResult SpawnChild(const ProcessSpec& spec);

}  // namespace slamsweep::orchestrator
