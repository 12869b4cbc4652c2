#pragma once

#include <filesystem>
#include <string_view>

namespace slamsweep::orchestrator::inline files {

/// Replaces `file` with `content` so that a reader (or a crash) sees either the old or the new file,
/// never a half-written one: writes a temporary file beside it, fsyncs it, renames it over `file`
/// and fsyncs the folder.
/// Throws InputError naming the file and the system error when it cannot be written.
/// kProcessCrash leaves out the two fsyncs: still never half-written for a reader or after a crash of a process,
/// but not made durable against a crash of the machine (for a file that is written again when lost).
enum class Durability { kMachineCrash, kProcessCrash };
void WriteFileAtomically(const std::filesystem::path& file, std::string_view content,
                         Durability durability = Durability::kMachineCrash);

}  // namespace slamsweep::orchestrator::inline files
