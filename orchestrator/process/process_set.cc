#include "orchestrator/process/process_set.h"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <string>

#include "orchestrator/process/child_reaping.h"
#include "orchestrator/process/outcome_reason.h"
#include "orchestrator/process/signal_wakeup.h"
#include "orchestrator/process/spawn.h"
#include "orchestrator/process/wake_up.h"

namespace slamsweep::orchestrator::inline process {
namespace {

// Per child and wake-up, so a flooding child cannot starve the others.
constexpr std::size_t kReadBudgetBytes = 1 << 20;

}  // namespace

ProcessSet::ProcessSet() {
  EnsureChildSignalHandler();
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGCHLD);
  pthread_sigmask(SIG_BLOCK, &set, &previous_mask_);
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
  RunningChild child(spec);
  child.started = ChildClock::now();  // wall time includes the start-up, as a user with a stopwatch sees it
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
  const auto now = ChildClock::now();
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
  child.first_usage_check = now + kUsagePollPeriod;
  children_.emplace(id, std::move(child));
  return id;
}

void ProcessSet::ReapEnded(std::vector<std::pair<Id, ProcessOutcome>>& ended) {
  for (auto it = children_.begin(); it != children_.end();) {
    siginfo_t info = {};
    // WNOWAIT: look, but leave the zombie in place until its group is killed (see ReapChild).
    int rc;
    while ((rc = ::waitid(P_PID, static_cast<id_t>(it->second.pid), &info, WEXITED | WNOHANG | WNOWAIT)) != 0 &&
           errno == EINTR) {
    }
    // rc != 0 (ECHILD) means somebody else reaped it; ReapChild() reports the status as lost.
    if (rc == 0 && info.si_pid == 0) {
      ++it;
      continue;
    }
    ended.emplace_back(it->first, ReapChild(it->second));
    it = children_.erase(it);
  }
}

void ProcessSet::Poll(ChildClock::time_point until) {
  std::vector<pollfd> fds;
  std::vector<RunningChild*> owners;
  fds.push_back({SignalWakeupFd(), POLLIN, 0});
  owners.push_back(nullptr);
  for (auto& [id, child] : children_) {
    if (child.output_fd < 0) continue;
    fds.push_back({child.output_fd, POLLIN, 0});
    owners.push_back(&child);
  }
  const auto now = ChildClock::now();
  const auto wait = std::clamp(until - now, ChildClock::duration::zero(), ChildClock::duration(kMaxSleep));
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
    if (fds[i].revents != 0) ReadChildOutput(*owners[i], kReadBudgetBytes);
  }
}

std::vector<std::pair<ProcessSet::Id, ProcessOutcome>> ProcessSet::WaitForAny() {
  std::vector<std::pair<Id, ProcessOutcome>> ended;
  for (;;) {
    ended.insert(ended.end(), std::make_move_iterator(pending_.begin()), std::make_move_iterator(pending_.end()));
    pending_.clear();
    ReapEnded(ended);
    if (!ended.empty() || children_.empty() || InterruptionPending() || TakeWakeUpRequest()) return ended;
    Poll(limits_.Enforce(children_, ChildClock::now()));
  }
}

void ProcessSet::Stop(Id id) {
  const auto found = children_.find(id);
  if (found != children_.end()) StopChild(found->second, StopCause::kInterrupt, ChildClock::now());
}

std::vector<std::pair<ProcessSet::Id, ProcessOutcome>> ProcessSet::TerminateAll() {
  std::vector<std::pair<Id, ProcessOutcome>> ended(std::make_move_iterator(pending_.begin()),
                                                   std::make_move_iterator(pending_.end()));
  pending_.clear();
  ReapEnded(ended);
  const auto now = ChildClock::now();
  for (auto& [id, child] : children_) {
    child.interrupt_signal = InterruptionGuard::Signal();
    StopChild(child, StopCause::kInterrupt, now);
  }
  while (!children_.empty()) {
    Poll(limits_.Enforce(children_, ChildClock::now()));
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

}  // namespace slamsweep::orchestrator::inline process
