#pragma once

#include <optional>
#include <string_view>

// Every state a run, a sweep or a sweep's report can be in, here and in the service's queue; run_status.cc is
// the only place that spells them.
namespace slamsweep::orchestrator::inline run {

/// What became of a run. result.json records kOk or kFailed; a run folder without a readable result.json
/// is kUnfinished or kUnreadable to whoever reads it.
enum class RunStatus {
  kOk,          ///< result.json says "ok"
  kFailed,      ///< result.json says "failed" (its reason says why)
  kUnfinished,  ///< run.json but no result.json: interrupted or still running
  kUnreadable,  ///< run.json or result.json could not be read
};

/// "ok", "failed", "unfinished", "unreadable".
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

// The service's queue (`slamsweep serve`).

/// A run's place in the service's queue. kQueued and kRunning are unfinished; kOk and kFailed were run
/// for this sweep; kReused took another sweep's identical ok run (or this sweep's own result
/// directory's); kCancelled never ran because its sweep was cancelled or could not go on.
enum class QueuedRunState { kQueued, kRunning, kOk, kFailed, kReused, kCancelled };
inline constexpr QueuedRunState kRunStates[] = {QueuedRunState::kQueued, QueuedRunState::kRunning,
                                                QueuedRunState::kOk,     QueuedRunState::kFailed,
                                                QueuedRunState::kReused, QueuedRunState::kCancelled};

/// A sweep's state: kQueued (nothing started yet), kRunning, kOk / kFailed (every run finished;
/// failed when one failed or the sweep could not go on), kCancelled.
enum class QueuedSweepState { kQueued, kRunning, kOk, kFailed, kCancelled };
inline constexpr QueuedSweepState kSweepStates[] = {QueuedSweepState::kQueued, QueuedSweepState::kRunning,
                                                    QueuedSweepState::kOk, QueuedSweepState::kFailed,
                                                    QueuedSweepState::kCancelled};

/// A sweep's HTML report: kNone until the sweep finished, then kWriting, kReady or kFailed.
enum class ReportState { kNone, kWriting, kReady, kFailed };

// Each queue state's name is its text in the service's queue.sqlite and in its HTTP API's JSON.

std::string_view ToString(QueuedRunState state);
std::string_view ToString(QueuedSweepState state);
std::string_view ToString(ReportState state);

/// The state named `text`; nullopt for a name that is no state (for readers that tolerate one).
std::optional<QueuedRunState> FindRunState(std::string_view text);
std::optional<QueuedSweepState> FindSweepState(std::string_view text);
std::optional<ReportState> FindReportState(std::string_view text);

/// The state named `text`; evaluator::InputError naming `text` when it is no state.
QueuedRunState ParseRunState(std::string_view text);
QueuedSweepState ParseSweepState(std::string_view text);

/// What the API and the page show for a sweep whose cancel was asked for and is not done yet.
std::string_view CancellingStateName();

/// ok, failed and cancelled: the sweep will not change any more.
bool IsFinished(QueuedSweepState state);
/// ok, failed and reused: the run has a result.
bool HasResult(QueuedRunState state);
/// queued and running: the run still has to run.
bool IsUnfinished(QueuedRunState state);

}  // namespace slamsweep::orchestrator::inline run
