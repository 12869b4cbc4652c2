#pragma once

#include <optional>
#include <string_view>

namespace slamsweep::orchestrator::service {

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

// Each state's name is its text in the queue's SQLite file and in the HTTP API's JSON; queue_states.cc
// is the only place that spells them.

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

}  // namespace slamsweep::orchestrator::service
