#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace slamsweep::orchestrator::inline worker {

/// What a program left in raw/, checked after it exited and before the worker reads anything there.
struct RawFolderCheck {
  /// Entries removed, as "raw/NAME (a symbolic link)".
  std::vector<std::string> removed;
  /// Bytes of the regular files that stay.
  std::uint64_t total_bytes = 0;
  /// A file (relative to the run folder) whose size reached the per-file limit; empty when none did.
  std::string file_at_limit;
};

/// Removes every entry of `raw` (recursively) that is neither a regular file nor a folder: a
/// symbolic link the worker would follow out of raw/ (to the reference, say), a FIFO that would
/// block it, a socket or device. Sums the rest and names a file of `file_size_limit_bytes` or more
/// (0 = no limit): the program was stopped there by RLIMIT_FSIZE.
RawFolderCheck CheckRawFolder(const std::filesystem::path& raw, std::uint64_t file_size_limit_bytes);

}  // namespace slamsweep::orchestrator::inline worker
