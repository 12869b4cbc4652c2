#pragma once

#include <signal.h>
#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "orchestrator/process/child_limits.h"
#include "orchestrator/process/interruption.h"
#include "orchestrator/process/process_outcome.h"
#include "orchestrator/process/process_spec.h"
#include "orchestrator/process/running_child.h"

namespace slamsweep::orchestrator::inline process {

/// Several child programs at once under one supervising loop (ninja's SubprocessSet): each child in
/// its own process group, stdin /dev/null, output captured into its capped log, timeout
/// (SIGTERM to the group, grace, SIGKILL), memory limit on the group, rusage from wait4().
/// When a child ends, its whole group gets SIGKILL, so no background grandchild outlives its run.
/// A sandboxed child (ProcessSpec::sandbox) is bubblewrap: its usage is counted over everything it
/// started, its process limit is watched, and its status comes from the sandbox's process 1.
///
/// Not thread-safe; use it from one thread. It blocks SIGCHLD in the constructing thread for its
/// lifetime (signals are taken only inside ppoll). The destructor SIGKILLs and reaps what is left.
class ProcessSet {
 public:
  using Id = std::uint64_t;

  ProcessSet();
  ~ProcessSet();
  ProcessSet(const ProcessSet&) = delete;
  ProcessSet& operator=(const ProcessSet&) = delete;

  /// Starts a child. Never throws for a program that cannot start (missing, not executable, bad
  /// working directory, log not writable): that child "ends" at once with kFailedToStart, returned by
  /// the next WaitForAny().
  Id Start(const ProcessSpec& spec);

  /// Blocks until >= 1 child ended (or an interruption arrived); returns the ended ones. Wakes up for
  /// timeouts and memory polls (every ~200 ms while a memory limit is set). Empty set: returns at once.
  /// After an interruption (InterruptionPending()) it returns at once (possibly with an empty list); the
  /// caller then calls TerminateAll(). It also returns, possibly empty, when another thread called
  /// RequestWakeUp() (orchestrator/process/wake_up.h).
  std::vector<std::pair<Id, ProcessOutcome>> WaitForAny();

  /// Ends one child the way TerminateAll ends them all (SIGTERM to its group, its grace, SIGKILL),
  /// without waiting: its outcome (kInterrupted, reason "stopped by the supervisor ...") comes from a
  /// later WaitForAny(). A child that already ended keeps its own outcome; unknown ids are ignored.
  void Stop(Id id);

  /// SIGTERM to every group, wait grace_s (each child's own), SIGKILL the rest; returns their
  /// outcomes (kInterrupted). Children that had already ended by themselves keep their real outcome.
  std::vector<std::pair<Id, ProcessOutcome>> TerminateAll();

  /// Children started whose outcome has not been returned yet (a failed start counts until then).
  std::size_t running() const { return children_.size() + pending_.size(); }

 private:
  /// Waits for output, a signal, or `until` (capped), and reads what arrived.
  void Poll(ChildClock::time_point until);
  /// Collects every child that has ended (non-blocking).
  void ReapEnded(std::vector<std::pair<Id, ProcessOutcome>>& ended);

  RunningChildren children_;
  std::vector<std::pair<Id, ProcessOutcome>> pending_;
  Id next_id_ = 1;
  LimitEnforcer limits_;
  sigset_t previous_mask_;
};

/// One child to completion (the worker's case). Honours interruption like ProcessSet: when
/// InterruptionPending(), it terminates the child's group itself and returns kInterrupted.
ProcessOutcome RunProcess(const ProcessSpec& spec);

}  // namespace slamsweep::orchestrator::inline process
