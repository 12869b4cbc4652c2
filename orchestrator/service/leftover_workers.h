#pragma once

#include <sys/types.h>

#include <filesystem>
#include <vector>

namespace slamsweep::orchestrator::service {

/// Processes left by a server that was killed (kill -9) while runs were in flight: workers started as
/// `PROGRAM worker RUN_DIR` with RUN_DIR under `sweeps_root`, and SLAM programs whose working
/// directory (their run's raw/) lies under it. Found through /proc, so a recycled pid that belongs to
/// something else is never taken for one of ours.
std::vector<pid_t> FindLeftoverProcesses(const std::filesystem::path& sweeps_root);

/// Ends those processes with their process groups: SIGTERM (a worker then stops its program and
/// removes its partial outputs), up to `grace_s`, then SIGKILL; returns how many there were, once they
/// are gone (or 5 s after the SIGKILL). Normally the parent-death signal ended them already.
std::size_t EndLeftoverProcesses(const std::filesystem::path& sweeps_root, double grace_s);

/// The Slurm executor's equivalent: job arrays a killed server submitted (their batch scripts lie in
/// `state_dir`, as squeue's command column shows) are cancelled with scancel, and this returns once
/// squeue no longer lists them (or after `wait_s`). Other users' and other servers' jobs are left alone.
/// Returns the job ids cancelled.
std::vector<std::string> EndLeftoverSlurmJobs(const std::filesystem::path& state_dir, double wait_s);

}  // namespace slamsweep::orchestrator::service
