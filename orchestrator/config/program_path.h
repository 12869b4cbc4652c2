#pragma once

#include <filesystem>
#include <string_view>

namespace slamsweep::orchestrator::inline config {

/// The file a program name stands for, as execvp would find it: a name without '/' is looked up in
/// PATH; a path with a '/' is taken as is when absolute, else relative to `base_dir`. Returns the
/// absolute, normalised path. Throws InputError saying what is wrong (not found in PATH, naming
/// PATH's folders; no such file; not a regular file; not executable).
std::filesystem::path ResolveProgram(std::string_view program, const std::filesystem::path& base_dir);

}  // namespace slamsweep::orchestrator::inline config
