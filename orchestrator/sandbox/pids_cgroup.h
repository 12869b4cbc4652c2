#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace slamsweep::orchestrator::inline sandbox {

/// One sandbox's own pids cgroup (cgroup v1 `pids` hierarchy, or cgroup v2 with the pids
/// controller), a child of this process's cgroup: every process and thread the sandbox starts counts,
/// whatever its user, and pids.events says exactly how many forks the limit refused. Only where this
/// process may make cgroups (root outside a container, typically); else a sandbox relies on
/// RLIMIT_NPROC (orchestrator/sandbox/sandbox_spec.h).
class PidsCgroup {
 public:
  /// A new cgroup with pids.max = `limit`, or nullptr with `why` saying why none can be made here.
  static std::unique_ptr<PidsCgroup> Create(std::uint64_t limit, std::string& why);
  /// Removes the cgroup, waiting a moment for its last tasks to leave.
  ~PidsCgroup();
  PidsCgroup(const PidsCgroup&) = delete;
  PidsCgroup& operator=(const PidsCgroup&) = delete;

  /// The file a process writes "0" into to join the cgroup (before it starts anything).
  std::filesystem::path ProcsFile() const { return folder_ / "cgroup.procs"; }
  /// Forks refused because the cgroup was at its limit, so far.
  std::uint64_t Refusals() const;

 private:
  explicit PidsCgroup(std::filesystem::path folder) : folder_(std::move(folder)) {}
  std::filesystem::path folder_;
};

}  // namespace slamsweep::orchestrator::inline sandbox
