#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "orchestrator/run/run_status.h"

namespace slamsweep::orchestrator::inline store {

/// The layout of the runs table that the run writer and the run reader share: which members of run.json and
/// result.json are columns, which are shared documents, and where the reader finds each column.

/// run.json members that differ from run to run of a group (the spec_own column); the rest of run.json is shared
/// (a document).
inline constexpr const char* kSpecOwnMembers[] = {"run_id", "iteration", "seed"};
/// result.json members kept as columns (read back as they are; absent ones come back as null).
inline constexpr const char* kResultColumns[] = {"failure_kind", "reason",      "exit_code",  "signal",     "wall_s",
                                                 "cpu_s",        "peak_rss_kb", "started_at", "finished_at"};
/// result.json members a query needs beyond its columns, kept as one shared document per distinct value.
inline constexpr const char* kResultSharedMembers[] = {"command", "outputs", "warnings", "odometry_is_reference"};
/// Where each of kResultColumns is in kRunColumns.
inline constexpr int kResultColumnIndex[] = {19, 20, 21, 22, 9, 23, 24, 25, 10};

/// The columns the reader selects from runs joined with its two documents (spec_doc, result_doc).
inline constexpr const char* kRunColumns =
    "runs.id, run_id, sweep_id, status, run_dir, algorithm, sequence, noise, iteration, wall_s, finished_at, "
    "parameters, odometry_is_reference, seeding, flags, spec_own, spec_doc.json, result_doc.json, result_digest, "
    "failure_kind, reason, exit_code, signal, cpu_s, peak_rss_kb, started_at";

/// JSON as the store keeps it: compact; invalid UTF-8 (a reason quoting a program's garbled output) is replaced
/// rather than refusing the whole run.
std::string StoredJsonText(const nlohmann::json& value);

/// A JSON text read back from `file`; an InputError naming the run and `what` (e.g. "run.json") when it does not
/// parse, since only an edited or damaged database holds such text.
nlohmann::json ParseStoredDocument(const std::filesystem::path& file, const std::string& run_id, const char* what,
                                   const std::string& text);

/// A runs.status as the writer stores it; anything else is an InputError (a damaged database).
RunStatus StoredRunStatus(const std::filesystem::path& file, const std::string& run_id, const std::string& text);

}  // namespace slamsweep::orchestrator::inline store
