#pragma once

// Waiting for a child process a test started (the real slamsweep binary, a browser).
#include <signal.h>
#include <sys/types.h>

#include <chrono>

namespace slamsweep::testing {

/// Exit code of child `pid` (128 + the signal when a signal ended it), or -1 when it did not end
/// within `limit` (it is then killed and reaped).
int WaitExit(pid_t pid, std::chrono::seconds limit);

}  // namespace slamsweep::testing
