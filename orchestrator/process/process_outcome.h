#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace slamsweep::orchestrator::inline process {

/// How a child ended. Every ending is data for the caller; none is an exception.
enum class ProcessEnding { kExited, kSignaled, kTimedOut, kMemoryLimit, kProcessLimit, kInterrupted, kFailedToStart };

/// "exited", "signaled", "timed_out", "memory_limit", "process_limit", "interrupted", "failed_to_start".
std::string_view EndingName(ProcessEnding ending);

/// What happened to one child program.
struct ProcessOutcome {
  ProcessEnding ending = ProcessEnding::kFailedToStart;
  /// The exit code when the child exited (also after a timeout's SIGTERM), else -1.
  int exit_code = -1;
  /// The signal that ended the child, if a signal did, else 0.
  int signal = 0;
  /// One human sentence: "exit code 3", "killed by SIGSEGV (signal 11)",
  /// "timed out after 2.0 s (SIGTERM, then SIGKILL after 5 s grace)",
  /// "peak memory 2.1 GB above the 2048 MB limit", "cannot start 'foo': No such file or directory".
  std::string reason;
  double wall_s = 0;
  /// From wait4()'s rusage: user + system time of the child and the descendants it waited for.
  double cpu_s = 0;
  /// ru_maxrss of the child (kB).
  std::int64_t peak_rss_kb = 0;
  std::uint64_t log_bytes_written = 0;
  /// True when the middle of the output was left out of the log (see ProcessSpec::log_cap_bytes).
  bool log_truncated = false;
  /// kFailedToStart because the sandbox could not be set up (no namespaces here, say), not the program.
  bool sandbox_failed = false;

  /// Exited by itself with exit code 0.
  bool ok() const { return ending == ProcessEnding::kExited && exit_code == 0; }
};

}  // namespace slamsweep::orchestrator::inline process
