#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace slamsweep::report::inline html {

/// A file name made from untrusted text (run id, algorithm, sequence): only [A-Za-z0-9_.-], no
/// leading dot, at most 64 characters. When anything had to change, "-" and 8 hex digits of a
/// hash of the original are appended, so "a/b" and "a_b" stay distinct. Never empty, never
/// "." or "..", never a path.
std::string SafeFileName(std::string_view text);

/// Whether `path` itself is a regular file; a symbolic link is not followed, so a link in a run
/// folder cannot bring a file from elsewhere into the report.
bool IsRegularFileNoFollow(const std::filesystem::path& path);

}  // namespace slamsweep::report::inline html
