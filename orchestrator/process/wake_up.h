#pragma once

namespace slamsweep::orchestrator::inline process {

// Wake-ups of a supervising thread by other threads of the same process. The service's scheduler
// blocks in its executor's Wait() (ProcessSet::WaitForAny, the Slurm executor's polling) while the
// HTTP threads accept sweeps and cancellations; they call RequestWakeUp() so that the scheduler
// starts or stops runs now instead of when the next worker ends. The request travels through the
// same self-pipe as the signals, so a wait can never miss it.

/// Makes the next (or the current) executor wait return, possibly with nothing ended.
/// Async-signal-safe and callable from any thread.
void RequestWakeUp();

/// Consumes a pending request: true when there was one since the last call.
bool TakeWakeUpRequest();

/// Sleeps up to `seconds`, returning early for a wake-up request or SIGINT/SIGTERM/SIGHUP (which the
/// InterruptionGuard keeps blocked outside waits). Does not consume the request: the caller checks
/// TakeWakeUpRequest() afterwards.
void SleepUnlessWoken(double seconds);

}  // namespace slamsweep::orchestrator::inline process
