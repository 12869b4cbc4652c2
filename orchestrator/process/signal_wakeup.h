#pragma once

namespace slamsweep::orchestrator::inline process {

// The self-pipe that slamsweep's signal handlers write to, so that a ProcessSet blocked in ppoll()
// wakes up even when the signal was delivered to another thread. Internal to orchestrator/process.

/// Read end (non-blocking, close-on-exec); the pipe is created on first use and lives for the process.
int SignalWakeupFd();
/// Async-signal-safe: writes one byte (a full pipe already means "wake up").
void NotifySignalWakeup();
/// Empties the pipe after a wake-up.
void DrainSignalWakeup();
/// Installs, once per process, a SIGCHLD handler that only calls NotifySignalWakeup(). Without a
/// handler SIGCHLD is ignored by default and would not interrupt ppoll().
void EnsureChildSignalHandler();

}  // namespace slamsweep::orchestrator::inline process
