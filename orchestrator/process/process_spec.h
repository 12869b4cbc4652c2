#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "orchestrator/sandbox/sandbox_spec.h"

namespace slamsweep::orchestrator::inline process {

/// How to run one child program. Plain data: the runner never changes it.
struct ProcessSpec {
  /// argv[0] is looked up in the runner's PATH when it has no '/'. Never a shell.
  std::vector<std::string> argv;
  /// Empty: the runner's current directory.
  std::filesystem::path working_dir;
  /// stdout and stderr of the child both go here, interleaved as written (one pipe). Empty: discarded
  /// (still read, so the child never blocks or gets SIGPIPE).
  std::filesystem::path log_path;
  /// The log keeps the first half and the last half of the output with a marker line between, so a
  /// program writing gigabytes cannot fill the disk. 0 = no cap. Caps below 256 bytes count as 256.
  std::uint64_t log_cap_bytes = 8 << 20;
  /// 0 = none. On expiry the whole process group gets SIGTERM, then SIGKILL after `grace_s`.
  double timeout_s = 0;
  double grace_s = 5;
  /// 0 = none. Checked every ~200 ms on the summed RSS of the child's process group; on excess the
  /// group gets SIGKILL at once (a program eating memory may not live through a grace period).
  std::uint64_t memory_limit_mb = 0;
  /// Variables of the runner's environment whose names start with one of these are not passed on.
  std::vector<std::string> removed_env_prefixes;
  /// Added to (or replacing in) the runner's environment, after the removal.
  std::vector<std::pair<std::string, std::string>> extra_env;
  /// Run the child in this sandbox (bubblewrap); absent: it sees and may do what the runner may. A
  /// sandboxed child's memory and processes are counted over its whole PID namespace, its exact exit
  /// status comes from the sandbox's process 1, and reaching `process_limit` ends it.
  std::optional<SandboxSpec> sandbox;
};

}  // namespace slamsweep::orchestrator::inline process
