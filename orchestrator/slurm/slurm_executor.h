#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "orchestrator/supervisor/executor.h"

namespace slamsweep::orchestrator::inline slurm {

/// How runs go to Slurm. Plain data; the defaults suit a cluster where the output directory and
/// the slamsweep binary are on a file system every node sees.
struct SlurmOptions {
  /// The slamsweep binary the array tasks exec as `PROGRAM worker RUN_DIR` (made absolute).
  std::filesystem::path worker_program;
  /// `--partition`; empty = the cluster's default partition.
  std::string partition;
  /// Appended to sbatch's arguments (after ours, so they can override them): "--account=slam", "--qos=low".
  std::vector<std::string> extra_sbatch_args;
  /// Seconds between state queries (scontrol / sacct) while waiting.
  double poll_interval_s = 5.0;
  /// The array's %throttle: at most this many tasks at once; 0 = as many as Slurm allows.
  std::size_t max_parallel = 0;
  /// Where batch scripts, manifests and Slurm's own task output go; it must be visible to the
  /// nodes. Empty = OUT/slurm beside OUT/runs/.
  std::filesystem::path state_dir;
  /// Memory the worker itself needs on top of the program's memory_limit_mb (reading the sequence,
  /// scoring), added to `--mem`.
  std::size_t worker_memory_overhead_mb = 1024;
};

/// Runs each run as a task of a Slurm job array. Start() only queues; the first Wait() submits
/// everything queued as ONE `sbatch --array` job whose tasks exec the same worker as the local
/// executor, then polls Slurm until tasks end. Per task `--time` covers the longest program timeout
/// plus the worker's overhead and `--mem` the largest memory limit plus worker_memory_overhead_mb.
/// Finished tasks come back as WorkerEnding whose reason names Slurm's state (TIMEOUT, OUT_OF_MEMORY,
/// FAILED with exit code or signal, CANCELLED, NODE_FAIL); it only matters when no result.json exists.
/// A failed submission or an unreachable controller fails the runs (data), never the sweep.
/// TerminateAll() scancels the jobs and returns the unfinished tasks as interrupted.
/// Slurm client commands run without a shell; SLURM_CONF and PATH come from the environment.
std::unique_ptr<Executor> MakeSlurmExecutor(const SlurmOptions& options);

}  // namespace slamsweep::orchestrator::inline slurm
