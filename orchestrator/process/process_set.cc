#include "orchestrator/process/process_set.h"

#include <poll.h>
#include <pthread.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <sstream>

#include "orchestrator/process/group_memory.h"
#include "orchestrator/process/outcome_reason.h"
#include "orchestrator/process/signal_wakeup.h"
#include "orchestrator/process/spawn.h"
#include "orchestrator/process/wake_up.h"

namespace slamsweep::orchestrator {
namespace {

using Clock = std::chrono::steady_clock;

constexpr auto kMemoryPollPeriod = std::chrono::milliseconds(200);
// A safety net only: signals wake the wait through the self-pipe; this bounds the delay should a
// wake-up be consumed elsewhere (another ProcessSet in another thread).
constexpr auto kMaxSleep = std::chrono::seconds(1);
// Per child and wake-up, so a flooding child cannot starve the others.
constexpr std::size_t kReadBudgetBytes = 1 << 20;
// After the child ended: what is still in the pipe, bounded because a grandchild outside the group
// could keep writing forever.
constexpr std::size_t kDrainBudgetBytes = 16 << 20;
// Enough for bubblewrap's one-line message when it cannot set a sandbox up.
constexpr std::size_t kOutputTailBytes = 512;

Clock::time_point After(Clock::time_point now, double seconds) {
  // Clamped so that an absurd timeout (1e300 s) cannot overflow the clock's integer ticks.
  seconds = std::clamp(seconds, 0.0, 1e9);
  return now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

double Seconds(const timeval& time) {
  return static_cast<double>(time.tv_sec) + static_cast<double>(time.tv_usec) * 1e-6;
}

void SignalGroup(pid_t group, int signal_number) { ::kill(-group, signal_number); }

}  // namespace

ProcessSet::ProcessSet() {
  EnsureChildSignalHandler();
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGCHLD);
  pthread_sigmask(SIG_BLOCK, &set, &previous_mask_);
  next_memory_poll_ = Clock::now();
}

ProcessSet::~ProcessSet() {
  for (auto& [id, child] : children_) {
    SignalGroup(child.pid, SIGKILL);
    ::waitpid(child.pid, nullptr, 0);
    if (child.output_fd >= 0) ::close(child.output_fd);
    if (child.status_fd >= 0) ::close(child.status_fd);
    child.log.Finish();
  }
  pthread_sigmask(SIG_SETMASK, &previous_mask_, nullptr);
}

ProcessSet::Id ProcessSet::Start(const ProcessSpec& spec) {
  const Id id = next_id_++;
  const std::string program = spec.argv.empty() ? std::string() : spec.argv.front();
  Child child(spec);
  child.started = Clock::now();  // wall time includes the start-up, as a user with a stopwatch sees it
  std::string error = child.log.Open(spec.log_path);
  SpawnResult spawned;
  if (error.empty()) {
    spawned = SpawnChild(spec);
    error = spawned.error;
  }
  if (!error.empty()) {
    ProcessOutcome outcome;
    outcome.ending = ProcessEnding::kFailedToStart;
    outcome.reason = StartFailureReason(program, error);
    // The log says why too, for whoever opens the run's folder first.
    child.log.Append(outcome.reason + "\n");
    child.log.Finish();
    outcome.log_bytes_written = child.log.bytes_written();
    pending_.emplace_back(id, std::move(outcome));
    return id;
  }
  const auto now = Clock::now();
  child.pid = spawned.pid;
  child.output_fd = spawned.output_fd;
  child.timeout_s = spec.timeout_s;
  child.grace_s = std::max(0.0, spec.grace_s);
  child.memory_limit_mb = spec.memory_limit_mb;
  child.sandboxed = spec.sandbox.has_value();
  child.status_fd = spawned.status_fd;
  if (child.status_fd >= 0) ::fcntl(child.status_fd, F_SETFL, ::fcntl(child.status_fd, F_GETFL) | O_NONBLOCK);
  if (spec.sandbox) child.process_limit = spec.sandbox->process_limit;
  if (spec.timeout_s > 0) child.timeout_at = After(now, spec.timeout_s);
  // A child's usage is first looked at one period after its start: a short run pays no scan of /proc.
  child.first_usage_check = now + kMemoryPollPeriod;
  children_.emplace(id, std::move(child));
  return id;
}

void ProcessSet::ReadOutput(Child& child, std::size_t max_bytes) {
  std::array<char, 64 * 1024> buffer;
  std::size_t total = 0;
  while (child.output_fd >= 0 && total < max_bytes) {
    const ssize_t n = ::read(child.output_fd, buffer.data(), buffer.size());
    if (n > 0) {
      child.log.Append(std::string_view(buffer.data(), static_cast<std::size_t>(n)));
      if (child.sandboxed) {
        child.output_tail.append(buffer.data(), static_cast<std::size_t>(n));
        if (child.output_tail.size() > kOutputTailBytes) {
          child.output_tail.erase(0, child.output_tail.size() - kOutputTailBytes);
        }
      }
      total += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EAGAIN) return;
    // EOF (every writer closed it) or an error: the child may still run; only its exit is awaited now.
    ::close(child.output_fd);
    child.output_fd = -1;
  }
}

ProcessOutcome ProcessSet::Reap(Child& child) {
  // The leader is a zombie still, so its pid cannot be reused as a group id yet: killing the group
  // now is safe, and it ends any grandchild that would otherwise hold the pipe open forever.
  SignalGroup(child.pid, SIGKILL);
  ReadOutput(child, kDrainBudgetBytes);
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
    outcome.wall_s = std::chrono::duration<double>(Clock::now() - child.started).count();
    child.log.Finish();
    outcome.log_bytes_written = child.log.bytes_written();
    outcome.log_truncated = child.log.truncated();
    return outcome;
  }
  outcome.wall_s = std::chrono::duration<double>(Clock::now() - child.started).count();
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

void ProcessSet::ReadSandboxStatus(Child& child, int monitor_status, ProcessOutcome& outcome) {
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

void ProcessSet::ReapEnded(std::vector<std::pair<Id, ProcessOutcome>>& ended) {
  for (auto it = children_.begin(); it != children_.end();) {
    siginfo_t info = {};
    // WNOWAIT: look, but leave the zombie in place until its group is killed (see Reap).
    int rc;
    while ((rc = ::waitid(P_PID, static_cast<id_t>(it->second.pid), &info, WEXITED | WNOHANG | WNOWAIT)) != 0 &&
           errno == EINTR) {
    }
    // rc != 0 (ECHILD) means somebody else reaped it; Reap() reports the status as lost.
    if (rc == 0 && info.si_pid == 0) {
      ++it;
      continue;
    }
    ended.emplace_back(it->first, Reap(it->second));
    it = children_.erase(it);
  }
}

void ProcessSet::Terminate(Child& child, StopCause cause, Clock::time_point now) {
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

Clock::time_point ProcessSet::EnforceLimits(Clock::time_point now) {
  Clock::time_point next = now + kMaxSleep;
  std::vector<pid_t> limited_groups;
  for (auto& [id, child] : children_) {
    if (child.timeout_at && now >= *child.timeout_at) Terminate(child, StopCause::kTimeout, now);
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
  if (now >= next_memory_poll_) {
    next_memory_poll_ = now + kMemoryPollPeriod;
    const auto usage = GroupUsageOf(limited_groups);
    for (auto& [id, child] : children_) {
      const auto found = usage.find(child.pid);
      if (found == usage.end() || child.stop_cause != StopCause::kNone) continue;
      const GroupUsage& used = found->second;
      if (child.memory_limit_mb > 0 && static_cast<std::uint64_t>(used.rss_kb) > child.memory_limit_mb * 1024) {
        child.over_limit_rss_kb = used.rss_kb;
        Terminate(child, StopCause::kMemory, now);
      }
      // The kernel refuses the task beyond the limit (RLIMIT_NPROC in the sandbox); the count here also
      // holds bubblewrap's monitor, outside the sandbox. A program at its limit is ended, as a fork
      // bomb must be.
      if (child.process_limit > 0 && static_cast<std::uint64_t>(used.tasks) > child.process_limit) {
        Terminate(child, StopCause::kProcesses, now);
      }
    }
  }
  return std::min(next, next_memory_poll_);
}

void ProcessSet::Poll(Clock::time_point until) {
  std::vector<pollfd> fds;
  std::vector<Child*> owners;
  fds.push_back({SignalWakeupFd(), POLLIN, 0});
  owners.push_back(nullptr);
  for (auto& [id, child] : children_) {
    if (child.output_fd < 0) continue;
    fds.push_back({child.output_fd, POLLIN, 0});
    owners.push_back(&child);
  }
  const auto now = Clock::now();
  const auto wait = std::clamp(until - now, Clock::duration::zero(), Clock::duration(kMaxSleep));
  const auto wait_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(wait).count();
  timespec timeout = {static_cast<time_t>(wait_ns / 1000000000), static_cast<long>(wait_ns % 1000000000)};
  // The signals we handle are blocked outside this call and open inside it only, so a SIGCHLD or
  // SIGINT that arrives after the last check still interrupts this wait instead of being missed.
  sigset_t open_mask;
  pthread_sigmask(SIG_SETMASK, nullptr, &open_mask);
  for (const int signal_number : {SIGCHLD, SIGINT, SIGTERM, SIGHUP}) sigdelset(&open_mask, signal_number);
  const int ready = ::ppoll(fds.data(), fds.size(), &timeout, &open_mask);
  if (ready <= 0) return;  // timeout or EINTR: the caller re-checks children and limits
  if (fds[0].revents != 0) DrainSignalWakeup();
  for (std::size_t i = 1; i < fds.size(); ++i) {
    if (fds[i].revents != 0) ReadOutput(*owners[i], kReadBudgetBytes);
  }
}

std::vector<std::pair<ProcessSet::Id, ProcessOutcome>> ProcessSet::WaitForAny() {
  std::vector<std::pair<Id, ProcessOutcome>> ended;
  for (;;) {
    ended.insert(ended.end(), std::make_move_iterator(pending_.begin()), std::make_move_iterator(pending_.end()));
    pending_.clear();
    ReapEnded(ended);
    if (!ended.empty() || children_.empty() || InterruptionPending() || TakeWakeUpRequest()) return ended;
    Poll(EnforceLimits(Clock::now()));
  }
}

void ProcessSet::Stop(Id id) {
  const auto found = children_.find(id);
  if (found != children_.end()) Terminate(found->second, StopCause::kInterrupt, Clock::now());
}

std::vector<std::pair<ProcessSet::Id, ProcessOutcome>> ProcessSet::TerminateAll() {
  std::vector<std::pair<Id, ProcessOutcome>> ended(std::make_move_iterator(pending_.begin()),
                                                   std::make_move_iterator(pending_.end()));
  pending_.clear();
  ReapEnded(ended);
  const auto now = Clock::now();
  for (auto& [id, child] : children_) {
    child.interrupt_signal = InterruptionGuard::Signal();
    Terminate(child, StopCause::kInterrupt, now);
  }
  while (!children_.empty()) {
    Poll(EnforceLimits(Clock::now()));
    ReapEnded(ended);
  }
  return ended;
}

ProcessOutcome RunProcess(const ProcessSpec& spec) {
  ProcessSet set;
  set.Start(spec);
  for (;;) {
    auto ended = set.WaitForAny();
    if (!ended.empty()) return std::move(ended.front().second);
    if (InterruptionPending()) {
      ended = set.TerminateAll();
      if (!ended.empty()) return std::move(ended.front().second);
    }
  }
}

}  // namespace slamsweep::orchestrator
