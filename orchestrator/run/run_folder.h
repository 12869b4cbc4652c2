#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "orchestrator/files/atomic_file.h"
#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline run {

/// Parses a JSON file. Throws InputError "FILE: ..." when it is missing, unreadable or not valid JSON
/// (with the parser's byte position).
nlohmann::json ReadJsonFile(const std::filesystem::path& file);

/// True for ids that are one harmless path component: [A-Za-z0-9_.-]+, not starting with '.',
/// at most 200 characters. Run ids are made that way (MakeRunId); this is the last line of defence
/// before an id becomes a path, because ids also arrive from merged stores and run.json files.
bool IsSafeRunId(std::string_view run_id);

/// OUT/runs/<run_id>. Throws InputError for an unsafe id (naming it), so that no id can place files
/// outside the output directory.
std::filesystem::path RunFolder(const std::filesystem::path& output_dir, std::string_view run_id);

/// Writes `value` to `file` through a temporary file, fsync and rename: a reader (or a sweep
/// started after a SIGKILL) sees the old file or the whole new one, never half of it.
/// With Durability::kProcessCrash, without the fsyncs (a run folder's run.json, written again when lost).
void WriteJsonAtomically(const std::filesystem::path& file, const nlohmann::json& value,
                         Durability durability = Durability::kMachineCrash);

/// What a run folder holds after its worker ended.
struct StoredResult {
  std::optional<nlohmann::json> result;
  /// Why `result` is empty: "no result.json", or the parse error naming the file.
  std::string problem;
};
StoredResult ReadRunResult(const std::filesystem::path& run_dir);

/// The run folder's run.json as written when the run started; nullopt when missing or not a JSON object.
std::optional<nlohmann::json> ReadRunSpecJson(const std::filesystem::path& run_dir);

/// The result record of a run whose worker left no usable result.json (it crashed, was killed or
/// could not start): status failed, failure_kind "internal" (or "interrupted"), the reason given.
nlohmann::json MissingResult(const RunSpec& run, const std::string& reason, bool interrupted);

/// Removes everything an unfinished attempt left in `run_dir` (the run is then started afresh or
/// given up). Errors are ignored: a file that cannot be removed is overwritten by the next attempt.
void RemovePartialRun(const std::filesystem::path& run_dir);

}  // namespace slamsweep::orchestrator::inline run
