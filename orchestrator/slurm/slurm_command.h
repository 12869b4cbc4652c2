#pragma once

#include <string>
#include <vector>

namespace slamsweep::orchestrator::inline slurm {

/// What a short Slurm client command (sbatch, scontrol, sacct, scancel) said.
struct CommandOutput {
  /// 0 on success; -1 when it could not start, was killed or timed out.
  int exit_code = -1;
  /// stdout and stderr together, as written (capped at 4 MB).
  std::string output;

  bool ok() const { return exit_code == 0; }
};

/// Runs `argv` (never through a shell; argv[0] looked up in PATH) to completion and returns its
/// output. Unlike RunProcess it does NOT stop the command when the sweep was interrupted: scancel
/// must still run after Ctrl-C. Commands that take longer than `timeout_s` are killed (SIGKILL to
/// their process group) and reported as exit code -1. Never throws for a command that fails.
CommandOutput RunSlurmCommand(const std::vector<std::string>& argv, double timeout_s = 60.0);

}  // namespace slamsweep::orchestrator::inline slurm
