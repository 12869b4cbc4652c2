#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "orchestrator/adapters/run_paths.h"
#include "orchestrator/run/run_spec.h"
#include "orchestrator/sandbox/sandbox_availability.h"
#include "orchestrator/sandbox/sandbox_spec.h"

namespace slamsweep::orchestrator::inline worker {

/// Set by `slamsweep run` and `serve` for their workers: more folders (':'-separated) that no
/// sandbox may show, such as the shared data folder with every reference, or the service's data
/// folder with every other sweep's results.
inline constexpr const char* kPrivateDirsVariable = "SLAMSWEEP_PRIVATE_DIRS";

/// Appends `folders` to SLAMSWEEP_PRIVATE_DIRS in this process's environment, for the workers it
/// starts: the shared data folder (`slamsweep run`), the service's data folder (`slamsweep serve`).
/// Call before any thread starts.
void AddPrivateDirs(const std::vector<std::filesystem::path>& folders);

/// For `slamsweep run` and `serve` with local workers: probes once how sandboxes get their /proc here
/// (orchestrator/sandbox/proc_choice.h) and tells the workers through SLAMSWEEP_SANDBOX_PROC; logs it
/// when they will have none. Nothing when bubblewrap is missing. Call before any thread starts.
void DecideSandboxProcForWorkers();

/// The sandbox a run's program runs in: read-only its own file, input/ and `reads` (what its adapter
/// knows it reads: the roster's installed libraries, Cartographer's Lua file, a command's
/// `read_only`), writable raw/ (its working folder), with the algorithm's disk and process limits
/// and network. When this process is root, the process limit is `pids_cgroup_procs` (the sandbox's
/// own pids cgroup) or, where none could be made, the sandbox runs as `nobody`, who is given raw/ and
/// input/ (RLIMIT_NPROC does not bind root). Throws InputError when one of those paths would show the run's truth: the
/// sweep's output folder (every run's reference.tum and result.json, results.sqlite, the reference-map cache), the
/// folders of the catalog files with the sequence's reference (the corrected log, the relations, a reference map) or a
/// folder of SLAMSWEEP_PRIVATE_DIRS. Such a folder inside the system paths every sandbox shows (a dataset under
/// /usr/share) is covered by an empty one instead. Its /proc is `fresh_proc`'s (ChosenSandboxProc).
SandboxSpec ProgramSandbox(const RunSpec& spec, const RunPaths& paths, const std::vector<std::filesystem::path>& reads,
                           const std::string& program, const SandboxPrograms& programs,
                           const std::filesystem::path& pids_cgroup_procs = {}, bool fresh_proc = true);

}  // namespace slamsweep::orchestrator::inline worker
