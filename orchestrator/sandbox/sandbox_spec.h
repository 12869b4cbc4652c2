#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace slamsweep::orchestrator::inline sandbox {

/// What a program started in a sandbox (bubblewrap, orchestrator/sandbox/bwrap_command.h) may see and
/// use. Its file system is built from nothing: the system folders it needs read-only (SystemPaths),
/// then exactly the paths named here at their own paths, a private /tmp, a minimal /dev and a /proc
/// of its own PID namespace (or none: `fresh_proc`). It runs in its own user, PID, mount, network, IPC and UTS
/// namespaces with no capability, no_new_privs, its own session, and dies with the process that started it.
struct SandboxSpec {
  /// Files and folders bound read-only (the program, its libraries and configuration, input/).
  std::vector<std::filesystem::path> read_only;
  /// Folders bound writable (raw/).
  std::vector<std::filesystem::path> writable;
  /// Folders inside the system paths that are covered by an empty read-only tmpfs (a dataset
  /// folder with a reference under /usr/share, say); what is bound inside one stays visible.
  std::vector<std::filesystem::path> hidden;
  /// false: a network namespace with only a loopback interface of its own.
  bool network = false;
  /// true: a /proc of its own PID namespace, and bubblewrap's --disable-userns. false, where the kernel
  /// refuses a fresh /proc (a container whose /proc has masked paths: proc_choice.h): no /proc at all, and
  /// nested user namespaces refused by a seccomp filter in process 1 (--disable-userns writes through /proc).
  bool fresh_proc = true;
  /// Processes and threads the sandbox may hold at once (RLIMIT_NPROC in its own user namespace, so
  /// that nothing else of the same user counts); 0 = no limit.
  std::uint64_t process_limit = 0;
  /// The largest file it may write (RLIMIT_FSIZE), also the size of its /tmp and /dev/shm; 0 = none.
  std::uint64_t file_size_limit_bytes = 0;
  /// The cgroup.procs file of the sandbox's own pids cgroup (pids_cgroup.h), which bubblewrap joins
  /// before it starts anything: the process limit for a sandbox started by root, who is exempt from
  /// RLIMIT_NPROC even mapped into a user namespace. Empty: none.
  std::filesystem::path pids_cgroup_procs;
  /// When set, bubblewrap itself is started under this user and group: root's way to a process limit
  /// where it can make no pids cgroup (a container), since RLIMIT_NPROC binds that user. Else the
  /// sandbox's processes keep the starting user's uid, mapped into their own user namespace.
  struct User {
    unsigned uid = 0;
    unsigned gid = 0;
  };
  std::optional<User> user;
  /// slamsweep-sandbox-init: process 1 of the sandbox (sets the limits, reports the exact status).
  std::filesystem::path init_program;
  /// bubblewrap.
  std::filesystem::path bwrap_program = "bwrap";
};

}  // namespace slamsweep::orchestrator::inline sandbox
