#pragma once

#include <signal.h>

namespace slamsweep::orchestrator::inline process {

/// Process-wide interruption by SIGINT, SIGTERM or SIGHUP (Ctrl-C, `kill`, a closed terminal).
/// While a guard lives, those signals no longer end the program: their handler only records the
/// signal and wakes a waiting ProcessSet (through a self-pipe), which then returns early so that the
/// caller can stop its children and exit 130 with its records intact. The signals are blocked in the
/// constructing thread except while ProcessSet waits (ppoll), so they cannot land between a check of
/// Interrupted() and the wait (ninja's approach).
///
/// Guards nest: the outermost one installs the handlers (and clears the flag) and restores the
/// previous ones when it goes. Create and destroy a guard in the same thread.
class InterruptionGuard {
 public:
  InterruptionGuard();
  ~InterruptionGuard();
  InterruptionGuard(const InterruptionGuard&) = delete;
  InterruptionGuard& operator=(const InterruptionGuard&) = delete;

  /// True once SIGINT/SIGTERM/SIGHUP arrived while a guard was alive. Stays true after the guard
  /// ends (so the caller can still choose exit code 130) until the next outermost guard starts.
  static bool Interrupted();
  /// Which signal interrupted (0 if none).
  static int Signal();

 private:
  sigset_t previous_mask_;
};

/// Interrupted() while a guard is still alive: what ProcessSet and RunProcess act on, so that an
/// interruption seen by an earlier guard does not stop children started after it ended.
bool InterruptionPending();

}  // namespace slamsweep::orchestrator::inline process
