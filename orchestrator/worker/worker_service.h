#pragma once

namespace slamsweep::orchestrator::inline worker {

/// `slamsweep worker --serve`: one long-lived worker of a sweep's worker pool (orchestrator/sweep/
/// worker_pool.h), which takes run folders one after another instead of starting a process per run.
/// Reads a run folder per line from `channel` (a socket; EOF ends the service), sends its stdout and
/// stderr to that run's worker.log while the run lasts, runs it with RunWorker (each SLAM program still
/// in its own sandboxed process) and answers "EXIT_CODE WALL_S CPU_S\n" on the same socket: RunWorker's
/// exit code, and the run's wall and CPU seconds (the worker's and its programs'). Returns 0 at EOF, and
/// 130 right after answering a run that SIGINT/SIGTERM/SIGHUP interrupted: an interrupted worker takes no
/// further run. A worker that dies loses only the run in hand, whose result.json it never committed.
int ServeWorkerRuns(int channel);

/// The descriptor a pool's worker finds its socket at (`slamsweep worker --serve`).
inline constexpr int kWorkerPoolChannelFd = 3;

}  // namespace slamsweep::orchestrator::inline worker
