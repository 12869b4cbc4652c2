#pragma once

#include <chrono>

#include "orchestrator/process/running_child.h"

namespace slamsweep::orchestrator::inline process {

/// How often the usage of children with a memory or process limit is looked at; a child is first
/// looked at one period after its start, so a short run pays no scan of /proc.
constexpr auto kUsagePollPeriod = std::chrono::milliseconds(200);
/// The longest a supervising wait sleeps. A safety net only: signals wake the wait through the
/// self-pipe; this bounds the delay should a wake-up be consumed elsewhere (another ProcessSet in
/// another thread).
constexpr auto kMaxSleep = std::chrono::seconds(1);

/// Starts ending `child` for `cause`: SIGKILL to its group at once for a memory or process limit
/// (a program eating memory may not live through a grace period), else SIGTERM and SIGKILL after its
/// grace (LimitEnforcer sends it). A child already stopping keeps its first cause.
void StopChild(RunningChild& child, StopCause cause, ChildClock::time_point now);

/// Enforces the timeouts, grace periods and memory and process limits of running children.
class LimitEnforcer {
 public:
  LimitEnforcer() : next_usage_poll_(ChildClock::now()) {}

  /// Stops the children past a timeout or limit at `now`, SIGKILLs those past their grace, and
  /// returns when it next needs to run.
  ChildClock::time_point Enforce(RunningChildren& children, ChildClock::time_point now);

 private:
  ChildClock::time_point next_usage_poll_;
};

}  // namespace slamsweep::orchestrator::inline process
