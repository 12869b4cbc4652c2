#pragma once

#include <filesystem>
#include <string_view>
#include <system_error>

namespace slamsweep::report::inline html {

// Files and folders of the site being written. Failures that make the site unusable throw
// evaluator::InputError naming the path.

/// Writes `content` to `path`, replacing what was there.
void WriteTextFile(const std::filesystem::path& path, std::string_view content);

/// Creates `dir` and its missing parents.
void MakeDirectories(const std::filesystem::path& dir);

/// Makes `out_dir` ready for a new site: the folder with runs/, sequences/, plots/ and files/, those of an
/// earlier report cleared. A folder that is not empty must carry the marker file an earlier report left, so
/// that a typo in -o (say, the home folder) is refused instead of filled with report files.
void PrepareOutputDir(const std::filesystem::path& out_dir);

/// A hard link where the file system allows (a report of 1,000 runs would otherwise copy every map and
/// log), else a copy; `error` says why neither worked. The report is a snapshot to read, so sharing the
/// bytes is safe.
void LinkOrCopy(const std::filesystem::path& from, const std::filesystem::path& to, std::error_code& error);

/// Links (else copies) result_dir/name into `out_dir`; false (and no stale copy left) when the sweep wrote
/// none. The sweep replaces these files by rename, never in place, so a link keeps the report's version.
bool CopyResultFile(const std::filesystem::path& result_dir, const std::filesystem::path& out_dir, const char* name);

}  // namespace slamsweep::report::inline html
