#pragma once

#include <filesystem>
#include <string>
#include <unordered_map>

namespace slamsweep::orchestrator::inline sweep {

/// Files that many runs of a sweep write byte for byte alike (a sequence's reference.tum, the same for every
/// algorithm, noise level and iteration) are stored once: the first of each content is kept, each later one is
/// replaced by a hard link to it. Run folders are not changed after their run, and a rerun removes its folder
/// before it writes, so a shared file is never written through another run's name.
class SharedRunFiles {
 public:
  /// Replaces `file` by a hard link to an earlier shared file of the same bytes, or remembers it as the first
  /// of its content. Leaves it as it is when it is missing or unreadable, when the earlier file is gone or
  /// changed, or when the file system refuses the link (it stays a copy).
  void Share(const std::filesystem::path& file);

 private:
  std::unordered_map<std::string, std::filesystem::path> first_with_content_;
};

}  // namespace slamsweep::orchestrator::inline sweep
