#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline supervisor {

/// How a worker ended, as the executor saw it. The run's own result is in its result.json; this
/// only matters when there is none (the worker crashed, was killed or never started).
struct WorkerEnding {
  std::string run_id;
  bool interrupted = false;
  /// One sentence for the run record when result.json is missing: "worker killed by SIGKILL".
  std::string reason;
};

/// Where runs are executed: this machine's worker processes, or a Slurm job array.
/// The Supervisor (supervisor.h) calls Start while it may start more, then Wait; the executor never
/// decides what to run (ninja's CommandRunner).
class Executor {
 public:
  virtual ~Executor() = default;
  /// Starts `slamsweep worker RUN_DIR` for a run whose run.json is already written.
  virtual void Start(const RunSpec& run, const std::filesystem::path& run_dir) = 0;
  /// Blocks until at least one started run ended or an interruption arrived; returns the ended ones
  /// (empty when interrupted with nothing finished, or when another thread called RequestWakeUp()).
  virtual std::vector<WorkerEnding> Wait() = 0;
  /// Ends one started run (a cancelled sweep's) without waiting: its ending comes from a later
  /// Wait(), marked interrupted unless it had ended by itself. Unknown or ended runs are ignored.
  virtual void Stop(const std::string& run_id) = 0;
  /// Ends every running worker (SIGTERM, grace, SIGKILL); returns them as interrupted.
  virtual std::vector<WorkerEnding> TerminateAll() = 0;
  virtual std::size_t Running() const = 0;
  /// True once SIGINT/SIGTERM/SIGHUP arrived.
  virtual bool Interrupted() const = 0;
};

}  // namespace slamsweep::orchestrator::inline supervisor
