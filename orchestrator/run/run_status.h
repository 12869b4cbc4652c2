#pragma once

#include <optional>
#include <string_view>

namespace slamsweep::orchestrator::inline run {

/// What became of a run. result.json records kOk or kFailed; a run folder without a readable result.json
/// is kUnfinished or kUnreadable to whoever reads it.
enum class RunStatus {
  kOk,          ///< result.json says "ok"
  kFailed,      ///< result.json says "failed" (its reason says why)
  kUnfinished,  ///< run.json but no result.json: interrupted or still running
  kUnreadable,  ///< run.json or result.json could not be read
};

/// "ok", "failed", "unfinished", "unreadable": the only place these words are written or read.
std::string_view RunStatusName(RunStatus status);

/// The status a result.json or a results database records: kOk for "ok", kFailed for "failed", nullopt otherwise.
std::optional<RunStatus> RecordedRunStatus(std::string_view text);

/// What became of a sweep, as the results database records it.
enum class SweepStatus {
  kRunning,      ///< begun and not finished (or its process died)
  kOk,           ///< every run ok
  kFailed,       ///< some run failed
  kInterrupted,  ///< stopped by a signal or a cancel before every run finished
};

/// "running", "ok", "failed", "interrupted".
std::string_view SweepStatusName(SweepStatus status);
/// The status of that name; nullopt for any other text.
std::optional<SweepStatus> SweepStatusFromName(std::string_view text);

}  // namespace slamsweep::orchestrator::inline run
