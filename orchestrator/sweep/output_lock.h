#pragma once

#include <filesystem>

namespace slamsweep::orchestrator::inline sweep {

/// Exclusive ownership of an output directory for one orchestrator at a time: a second
/// `slamsweep run` (or merge) on the same directory stops with an InputError naming the holder
/// instead of interleaving writes. An flock on OUT/.lock: the kernel releases it when the holder
/// dies, even by SIGKILL, so a crashed sweep never leaves a stale lock behind.
class OutputLock {
 public:
  /// Creates `directory` if needed. Throws InputError when another process holds the lock.
  explicit OutputLock(const std::filesystem::path& directory);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace slamsweep::orchestrator::inline sweep
