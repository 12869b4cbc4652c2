#include "orchestrator/process/child_limits.h"

#include <signal.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "orchestrator/process/group_memory.h"

namespace slamsweep::orchestrator::inline process {

void StopChild(RunningChild& child, StopCause cause, ChildClock::time_point now) {
  if (child.stop_cause != StopCause::kNone) return;  // already stopping; keep the first cause
  child.stop_cause = cause;
  if (cause == StopCause::kMemory || cause == StopCause::kProcesses) {
    SignalGroup(child.pid, SIGKILL);
    child.sent_kill = true;
    return;
  }
  SignalGroup(child.pid, SIGTERM);
  child.kill_at = After(now, child.grace_s);
}

ChildClock::time_point LimitEnforcer::Enforce(RunningChildren& children, ChildClock::time_point now) {
  ChildClock::time_point next = now + kMaxSleep;
  std::vector<pid_t> limited_groups;
  for (auto& [id, child] : children) {
    if (child.timeout_at && now >= *child.timeout_at) StopChild(child, StopCause::kTimeout, now);
    if (child.kill_at && !child.sent_kill) {
      if (now >= *child.kill_at) {
        SignalGroup(child.pid, SIGKILL);
        child.sent_kill = true;
      } else {
        next = std::min(next, *child.kill_at);
      }
    }
    if (child.timeout_at && child.stop_cause == StopCause::kNone) next = std::min(next, *child.timeout_at);
    const bool limited = child.memory_limit_mb > 0 || child.process_limit > 0;
    if (limited && child.stop_cause == StopCause::kNone) {
      if (now >= child.first_usage_check) {
        limited_groups.push_back(child.pid);
      } else {
        next = std::min(next, child.first_usage_check);
      }
    }
  }
  if (limited_groups.empty()) return next;
  if (now >= next_usage_poll_) {
    next_usage_poll_ = now + kUsagePollPeriod;
    const auto usage = GroupUsageOf(limited_groups);
    for (auto& [id, child] : children) {
      const auto found = usage.find(child.pid);
      if (found == usage.end() || child.stop_cause != StopCause::kNone) continue;
      const GroupUsage& used = found->second;
      if (child.memory_limit_mb > 0 && static_cast<std::uint64_t>(used.rss_kb) > child.memory_limit_mb * 1024) {
        child.over_limit_rss_kb = used.rss_kb;
        StopChild(child, StopCause::kMemory, now);
      }
      // The kernel refuses the task beyond the limit (RLIMIT_NPROC in the sandbox); the count here also
      // holds bubblewrap's monitor, outside the sandbox. A program at its limit is ended, as a fork
      // bomb must be.
      if (child.process_limit > 0 && static_cast<std::uint64_t>(used.tasks) > child.process_limit) {
        StopChild(child, StopCause::kProcesses, now);
      }
    }
  }
  return std::min(next, next_usage_poll_);
}

}  // namespace slamsweep::orchestrator::inline process
