#pragma once

#include <cstdint>
#include <string>

namespace slamsweep::orchestrator::inline process {

// The one-sentence reasons of ProcessOutcome, kept in one place so that result.json, the status
// line and the tests agree on their wording.

/// "exit code 3".
std::string ExitReason(int exit_code);
/// "killed by SIGSEGV (signal 11)".
std::string SignalReason(int signal_number);
/// How a child that was asked to stop with SIGTERM ended: "SIGTERM" when that was enough,
/// "SIGTERM, then SIGKILL after 5 s grace" when it was not.
std::string StopReason(bool needed_kill, double grace_s);
/// "timed out after 2.0 s (SIGTERM, then SIGKILL after 5 s grace)".
std::string TimeoutReason(double timeout_s, bool needed_kill, double grace_s);
/// "peak memory 2.1 GB above the 2048 MB limit" (MB below 1 GB).
std::string MemoryReason(std::int64_t group_rss_kb, std::uint64_t limit_mb);
/// "reached the process limit: 512 processes and threads at once (process_limit)".
std::string ProcessLimitReason(std::uint64_t limit);
/// "the sandbox could not be set up (bwrap exited with 1: bwrap: No permissions to create new namespace)".
std::string SandboxFailureReason(int exit_code, const std::string& message);
/// "interrupted by SIGINT (SIGTERM)"; without an interrupting signal (the supervisor stopped the
/// child on its own) "stopped by the supervisor (SIGTERM)".
std::string InterruptReason(int interrupt_signal, bool needed_kill, double grace_s);
/// "cannot start 'foo': No such file or directory".
std::string StartFailureReason(const std::string& program, const std::string& detail);

}  // namespace slamsweep::orchestrator::inline process
