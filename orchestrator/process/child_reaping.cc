#include "orchestrator/process/child_reaping.h"

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <sstream>
#include <string>

#include "orchestrator/process/outcome_reason.h"

namespace slamsweep::orchestrator::inline process {
namespace {

// After the child ended: what is still in the pipe, bounded because a grandchild outside the group
// could keep writing forever.
constexpr std::size_t kDrainBudgetBytes = 16 << 20;

double Seconds(const timeval& time) {
  return static_cast<double>(time.tv_sec) + static_cast<double>(time.tv_usec) * 1e-6;
}

/// A sandboxed child's outcome from its status lines, when nothing stopped it.
void ReadSandboxStatus(RunningChild& child, int monitor_status, ProcessOutcome& outcome) {
  std::string lines;
  std::array<char, 256> buffer;
  ssize_t n;
  while (child.status_fd >= 0) {
    n = ::read(child.status_fd, buffer.data(), buffer.size());
    if (n > 0) {
      lines.append(buffer.data(), static_cast<std::size_t>(n));
    } else if (!(n < 0 && errno == EINTR)) {
      break;
    }
  }
  std::istringstream in(lines);
  std::string what;
  long long value = 0;
  while (in >> what >> value) {
    if (what == "status") {
      // The program's own wait status: bubblewrap's exit code cannot tell "killed by signal N" from
      // "exit code 128 + N".
      const int status = static_cast<int>(value);
      outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      outcome.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
      outcome.ending = WIFSIGNALED(status) ? ProcessEnding::kSignaled : ProcessEnding::kExited;
      outcome.reason = WIFSIGNALED(status) ? SignalReason(outcome.signal) : ExitReason(outcome.exit_code);
      return;
    }
    if (what == "exec") {
      outcome.ending = ProcessEnding::kFailedToStart;
      outcome.exit_code = -1;
      outcome.signal = 0;
      outcome.reason =
          StartFailureReason("the program", std::string(std::strerror(static_cast<int>(value))) + " (in its sandbox)");
      return;
    }
  }
  // No status: the sandbox never started the program. bubblewrap said why in its last line.
  std::string message = child.output_tail;
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  if (const auto newline = message.rfind('\n'); newline != std::string::npos) message.erase(0, newline + 1);
  outcome.ending = ProcessEnding::kFailedToStart;
  outcome.sandbox_failed = true;
  outcome.reason = SandboxFailureReason(WIFEXITED(monitor_status) ? WEXITSTATUS(monitor_status) : -1, message);
  outcome.exit_code = -1;
  outcome.signal = 0;
}

}  // namespace

ProcessOutcome ReapChild(RunningChild& child) {
  // The leader is a zombie still, so its pid cannot be reused as a group id yet: killing the group
  // now is safe, and it ends any grandchild that would otherwise hold the pipe open forever.
  SignalGroup(child.pid, SIGKILL);
  ReadChildOutput(child, kDrainBudgetBytes);
  if (child.output_fd >= 0) ::close(child.output_fd);
  child.output_fd = -1;

  int status = 0;
  rusage usage = {};
  pid_t reaped;
  while ((reaped = ::wait4(child.pid, &status, 0, &usage)) < 0 && errno == EINTR) {
  }
  ProcessOutcome outcome;
  if (reaped != child.pid) {
    // Only possible when other code in this process waits for any child (waitpid(-1)).
    outcome.ending = ProcessEnding::kExited;
    outcome.reason = "exit status lost: the process was reaped by other code";
    outcome.wall_s = std::chrono::duration<double>(ChildClock::now() - child.started).count();
    child.log.Finish();
    outcome.log_bytes_written = child.log.bytes_written();
    outcome.log_truncated = child.log.truncated();
    return outcome;
  }
  outcome.wall_s = std::chrono::duration<double>(ChildClock::now() - child.started).count();
  outcome.cpu_s = Seconds(usage.ru_utime) + Seconds(usage.ru_stime);
  outcome.peak_rss_kb = usage.ru_maxrss;
  if (WIFEXITED(status)) outcome.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);

  switch (child.stop_cause) {
    case StopCause::kMemory:
      outcome.ending = ProcessEnding::kMemoryLimit;
      outcome.reason = MemoryReason(child.over_limit_rss_kb, child.memory_limit_mb);
      break;
    case StopCause::kProcesses:
      outcome.ending = ProcessEnding::kProcessLimit;
      outcome.reason = ProcessLimitReason(child.process_limit);
      break;
    case StopCause::kTimeout:
      outcome.ending = ProcessEnding::kTimedOut;
      outcome.reason = TimeoutReason(child.timeout_s, child.sent_kill, child.grace_s);
      break;
    case StopCause::kInterrupt:
      outcome.ending = ProcessEnding::kInterrupted;
      outcome.reason = InterruptReason(child.interrupt_signal, child.sent_kill, child.grace_s);
      break;
    case StopCause::kNone:
      outcome.ending = WIFSIGNALED(status) ? ProcessEnding::kSignaled : ProcessEnding::kExited;
      outcome.reason = WIFSIGNALED(status) ? SignalReason(outcome.signal) : ExitReason(outcome.exit_code);
      if (child.sandboxed) ReadSandboxStatus(child, status, outcome);
      break;
  }
  if (child.status_fd >= 0) ::close(child.status_fd);
  child.status_fd = -1;
  child.log.Finish();
  outcome.log_bytes_written = child.log.bytes_written();
  outcome.log_truncated = child.log.truncated();
  return outcome;
}

}  // namespace slamsweep::orchestrator::inline process
