#pragma once

#include <chrono>
#include <cstddef>

#include "orchestrator/supervisor/executor.h"
#include "orchestrator/supervisor/run_source.h"

namespace slamsweep::orchestrator::inline supervisor {

struct SupervisorOptions {
  /// Runs at once (>= 1).
  std::size_t jobs = 1;
  /// After an interruption (or a drain the source requests), how long running runs may go on
  /// before they are terminated; 0 terminates them at once.
  double drain_grace_s = 0.0;
  /// Times starting and waiting as the phases "start" and "wait" (phase_times.h): the sweep process
  /// reports them; the service leaves them out of its report thread's totals.
  bool time_phases = false;
};

/// The one supervising loop over an Executor, for `slamsweep run` and `slamsweep serve` alike: each
/// turn it starts runs while fewer than `jobs` run and the source gives one, then waits for endings
/// and hands them back. It ends when nothing runs and the source awaits nothing more, or when a
/// drain is over: every run ended within the grace period, or those left were terminated.
class Supervisor {
 public:
  Supervisor(Executor& executor, SupervisorOptions options);

  /// Runs `source` to its end (see above). Must be called from the thread that owns the executor.
  void Run(RunSource& source);

 private:
  using Clock = std::chrono::steady_clock;

  void NoticeDrain(RunSource& source);
  void StartWhileAllowed(RunSource& source);
  void WaitForEndings(RunSource& source);
  void Terminate(RunSource& source);

  Executor& executor_;
  SupervisorOptions options_;
  bool draining_ = false;
  Clock::time_point drain_deadline_;
};

}  // namespace slamsweep::orchestrator::inline supervisor
