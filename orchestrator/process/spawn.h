#pragma once

#include <string>

#include <sys/types.h>

#include "orchestrator/process/process_spec.h"

namespace slamsweep::orchestrator::inline process {

/// A started child, or why it could not start.
struct SpawnResult {
  pid_t pid = -1;
  /// Read end of the pipe that carries the child's stdout and stderr (non-blocking, close-on-exec); -1 when
  /// ChildStreams sends both elsewhere.
  int output_fd = -1;
  /// Read end of the sandbox's status pipe (close-on-exec, blocking), -1 when not sandboxed: the
  /// status lines of slamsweep-sandbox-init (orchestrator/sandbox), complete once the child ended.
  int status_fd = -1;
  /// Empty on success; else the detail of the failure ("No such file or directory").
  std::string error;
};

/// Standard streams of a child other than SpawnChild's defaults; -1 keeps the default. The child gets
/// duplicates: the caller keeps, and closes, its own descriptors.
struct ChildStreams {
  /// Read as the child's stdin instead of /dev/null.
  int stdin_fd = -1;
  /// The child's stderr instead of the output pipe.
  int stderr_fd = -1;
  /// stdout to /dev/null instead of the output pipe.
  bool discard_stdout = false;

  /// Nothing goes into the output pipe, so SpawnChild makes none for the caller.
  bool OutputElsewhere() const { return stderr_fd >= 0 && discard_stdout; }
};

/// Starts `spec.argv` (Boost.Process) in its own process group (pgid = pid) with stdin from
/// /dev/null, stdout+stderr into one pipe, default signal dispositions, an empty signal mask, and
/// PR_SET_PDEATHSIG(SIGTERM) so a supervisor that dies does not leave programs behind. Note that the
/// kernel sends that signal when the spawning THREAD ends, so spawn from a long-lived thread.
/// With spec.sandbox, the child is bubblewrap running the program in that sandbox. `streams` replaces
/// the standard streams named there.
/// Never throws for a program that cannot start. The caller owns the pid (reaps it) and the fds.
SpawnResult SpawnChild(const ProcessSpec& spec, const ChildStreams& streams = {});

}  // namespace slamsweep::orchestrator::inline process
