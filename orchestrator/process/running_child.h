#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "orchestrator/process/capped_log.h"
#include "orchestrator/process/process_spec.h"

namespace slamsweep::orchestrator::inline process {

// The state ProcessSet keeps per started child, shared by its limit enforcement and reaping.
// Internal to orchestrator/process.

using ChildClock = std::chrono::steady_clock;

/// Why the supervisor is ending a child; kNone while the child runs on its own.
enum class StopCause { kNone, kTimeout, kMemory, kProcesses, kInterrupt };

/// One started child: its descriptors, log, limits and how far its stopping got.
struct RunningChild {
  explicit RunningChild(const ProcessSpec& spec) : log(spec.log_cap_bytes) {}
  pid_t pid = -1;
  int output_fd = -1;
  CappedLog log;
  ChildClock::time_point started;
  ChildClock::time_point first_usage_check;
  std::optional<ChildClock::time_point> timeout_at;
  double timeout_s = 0;
  double grace_s = 0;
  std::uint64_t memory_limit_mb = 0;
  /// Sandboxed children only: the status pipe of slamsweep-sandbox-init and what came through it.
  bool sandboxed = false;
  int status_fd = -1;
  std::uint64_t process_limit = 0;
  /// The end of the output, for the message of a sandbox that could not be set up.
  std::string output_tail;
  StopCause stop_cause = StopCause::kNone;
  std::optional<ChildClock::time_point> kill_at;  // set once SIGTERM went to the group
  bool sent_kill = false;
  std::int64_t over_limit_rss_kb = 0;
  int interrupt_signal = 0;
};

/// The children of a ProcessSet by their id.
using RunningChildren = std::map<std::uint64_t, RunningChild>;

/// `now` plus `seconds`, clamped to [0, 1e9] s so that an absurd timeout (1e300 s) cannot overflow
/// the clock's integer ticks.
ChildClock::time_point After(ChildClock::time_point now, double seconds);

/// Sends `signal_number` to the whole process group led by `group`.
void SignalGroup(pid_t group, int signal_number);

/// Reads up to `max_bytes` of the child's output into its log (and, sandboxed, its output tail)
/// without blocking; closes the pipe at EOF or on an error.
void ReadChildOutput(RunningChild& child, std::size_t max_bytes);

}  // namespace slamsweep::orchestrator::inline process
