#include "orchestrator/supervisor/supervisor.h"

#include <optional>
#include <vector>

#include "orchestrator/phase_times/phase_times.h"
#include "orchestrator/process/wake_up.h"

namespace slamsweep::orchestrator::inline supervisor {

Supervisor::Supervisor(Executor& executor, SupervisorOptions options) : executor_(executor), options_(options) {}

void Supervisor::Run(RunSource& source) {
  for (;;) {
    NoticeDrain(source);
    source.BeginTurn(executor_);
    if (!draining_) StartWhileAllowed(source);
    source.EndTurn();
    if (draining_) {
      if (executor_.Running() == 0) return;
      if (Clock::now() >= drain_deadline_) {
        Terminate(source);
        return;
      }
    } else if (executor_.Running() == 0 && !source.AwaitsMore()) {
      return;
    }
    if (executor_.Running() > 0) {
      WaitForEndings(source);
    } else {
      // Nothing runs and more may come: sleep until a wake-up (a submission, a cancel) or a signal.
      SleepUnlessWoken(1.0);
      TakeWakeUpRequest();
    }
  }
}

void Supervisor::NoticeDrain(RunSource& source) {
  if (draining_ || !(executor_.Interrupted() || source.DrainRequested())) return;
  draining_ = true;
  source.Draining();
  drain_deadline_ =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options_.drain_grace_s));
}

void Supervisor::StartWhileAllowed(RunSource& source) {
  while (executor_.Running() < options_.jobs && !executor_.Interrupted()) {
    const std::optional<RunStart> start = source.Next();
    if (!start) return;
    try {
      std::optional<PhaseTimer> phase;
      if (options_.time_phases) phase.emplace("start");
      executor_.Start(*start->run, start->run_dir);
    } catch (const std::exception& error) {
      if (!source.StartFailed(error)) throw;
      continue;
    }
    source.Started(*start);
  }
}

void Supervisor::WaitForEndings(RunSource& source) {
  std::vector<WorkerEnding> endings;
  {
    std::optional<PhaseTimer> phase;
    if (options_.time_phases) phase.emplace("wait");
    endings = executor_.Wait();
  }
  if (endings.empty()) {
    // A wake-up, or an interruption: then Wait returns at once while the grace period lets runs
    // finish, so pause a little (up to a wake-up) rather than spin.
    if (options_.drain_grace_s > 0 && executor_.Interrupted()) SleepUnlessWoken(0.2);
    TakeWakeUpRequest();
  }
  for (const WorkerEnding& ending : endings) source.Ended(ending);
}

void Supervisor::Terminate(RunSource& source) {
  source.Terminating(executor_.Running());
  for (const WorkerEnding& ending : executor_.TerminateAll()) source.Ended(ending);
  source.EndTurn();
}

}  // namespace slamsweep::orchestrator::inline supervisor
