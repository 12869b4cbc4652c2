#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace slamsweep::orchestrator::inline slurm {

/// One Slurm job array: task i runs the run folder on line i + 1 of the manifest.
struct ArrayJobRequest {
  std::string job_name;
  std::size_t task_count = 0;
  /// The array's %throttle; 0 = none.
  std::size_t max_parallel = 0;
  /// Per task (`--time`), >= 1.
  std::int64_t time_limit_min = 1;
  /// Per task (`--mem`); 0 = do not ask (the partition's default).
  std::uint64_t memory_mb = 0;
  std::string partition;
  std::vector<std::string> extra_args;
  std::filesystem::path script_path;
  /// Where Slurm writes what the batch script itself prints before it hands over to the worker
  /// (the worker's own output goes to RUN_DIR/worker.log).
  std::filesystem::path slurm_output_pattern;
};

/// `--time` in whole minutes for a task whose program may run `timeout_s` and whose worker needs
/// `overhead_s` more (rounded up, at least 1: Slurm's smallest limit).
std::int64_t TimeLimitMinutes(double timeout_s, double overhead_s);

/// `--mem` in MB for a program limited to `memory_limit_mb` plus the worker's own `overhead_mb`;
/// 0 when the program has no limit (then the task does not ask for memory).
std::uint64_t TaskMemoryMb(std::uint64_t memory_limit_mb, std::uint64_t overhead_mb);

/// The sbatch argv (no shell): `sbatch --parsable --array=0-(n-1)[%k] --time=.. [--mem=..M] ... SCRIPT`.
/// Extra arguments come last before the script, so they can override ours.
std::vector<std::string> SbatchArgv(const ArrayJobRequest& request);

/// The batch script: picks its run folder from `manifest` by $SLURM_ARRAY_TASK_ID and execs
/// `WORKER_PROGRAM worker RUN_DIR` with its output in RUN_DIR/worker.log.
std::string BatchScript(const std::filesystem::path& worker_program, const std::filesystem::path& manifest);

/// `text` as one single-quoted POSIX shell word.
std::string ShellQuote(const std::string& text);

/// Reads the job id from `sbatch --parsable` output ("123" or "123;cluster"); -1 if there is none.
std::int64_t ParseSbatchJobId(const std::string& output);

}  // namespace slamsweep::orchestrator::inline slurm
