#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace slamsweep::orchestrator::inline input_cache {

/// SHA-256 of `file` (Sha256OfFile), remembered in `memo_dir` under the file's identity (path, device,
/// inode, size, modification and change times to the nanosecond), so that a sweep's thousands of runs
/// read a large log once for its digest. Any change to the file changes its change time; a file changed in
/// the last 3 s (which could change again within one tick of the file system's clock) is not remembered,
/// so a remembered digest is never one of other contents. Throws InputError naming the file when it cannot
/// be read; a memo that cannot be written is only not remembered.
std::string MemoisedSha256(const std::filesystem::path& file, const std::filesystem::path& memo_dir);

/// Writes `content` to `file` through a temporary file of a name no other process or host uses, renamed
/// into place: a reader sees the old file or the whole new one. Not synced: a cache entry lost to a crash
/// is made again. Throws InputError naming the file when it cannot be written.
void ReplaceFile(const std::filesystem::path& file, std::string_view content);

}  // namespace slamsweep::orchestrator::inline input_cache
