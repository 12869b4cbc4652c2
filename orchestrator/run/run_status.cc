#include "orchestrator/run/run_status.h"

#include <array>
#include <utility>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator::inline run {

std::string_view RunStatusName(RunStatus status) {
  switch (status) {
    case RunStatus::kOk:
      return "ok";
    case RunStatus::kFailed:
      return "failed";
    case RunStatus::kUnfinished:
      return "unfinished";
    case RunStatus::kUnreadable:
      return "unreadable";
  }
  return "unknown";
}

std::optional<RunStatus> RecordedRunStatus(std::string_view text) {
  for (const RunStatus status : {RunStatus::kOk, RunStatus::kFailed}) {
    if (text == RunStatusName(status)) return status;
  }
  return std::nullopt;
}

std::string_view SweepStatusName(SweepStatus status) {
  switch (status) {
    case SweepStatus::kRunning:
      return "running";
    case SweepStatus::kOk:
      return "ok";
    case SweepStatus::kFailed:
      return "failed";
    case SweepStatus::kInterrupted:
      return "interrupted";
  }
  return "unknown";
}

std::optional<SweepStatus> SweepStatusFromName(std::string_view text) {
  for (const SweepStatus status :
       {SweepStatus::kRunning, SweepStatus::kOk, SweepStatus::kFailed, SweepStatus::kInterrupted}) {
    if (text == SweepStatusName(status)) return status;
  }
  return std::nullopt;
}

namespace {

constexpr std::array<std::pair<QueuedRunState, std::string_view>, 6> kRunNames = {{
    {QueuedRunState::kQueued, "queued"},
    {QueuedRunState::kRunning, "running"},
    {QueuedRunState::kOk, "ok"},
    {QueuedRunState::kFailed, "failed"},
    {QueuedRunState::kReused, "reused"},
    {QueuedRunState::kCancelled, "cancelled"},
}};

constexpr std::array<std::pair<QueuedSweepState, std::string_view>, 5> kSweepNames = {{
    {QueuedSweepState::kQueued, "queued"},
    {QueuedSweepState::kRunning, "running"},
    {QueuedSweepState::kOk, "ok"},
    {QueuedSweepState::kFailed, "failed"},
    {QueuedSweepState::kCancelled, "cancelled"},
}};

constexpr std::array<std::pair<ReportState, std::string_view>, 4> kReportNames = {{
    {ReportState::kNone, "none"},
    {ReportState::kWriting, "writing"},
    {ReportState::kReady, "ready"},
    {ReportState::kFailed, "failed"},
}};

template <typename State, std::size_t N>
std::string_view NameOf(const std::array<std::pair<State, std::string_view>, N>& names, State state) {
  for (const auto& [known, name] : names) {
    if (known == state) return name;
  }
  return {};  // unreachable: every enumerator has a name
}

template <typename State, std::size_t N>
std::optional<State> StateNamed(const std::array<std::pair<State, std::string_view>, N>& names, std::string_view text) {
  for (const auto& [state, name] : names) {
    if (name == text) return state;
  }
  return std::nullopt;
}

template <typename State, std::size_t N>
State ParseState(const std::array<std::pair<State, std::string_view>, N>& names, std::string_view text,
                 std::string_view what) {
  if (const std::optional<State> state = StateNamed(names, text)) return *state;
  std::string expected;
  for (const auto& [state, name] : names) expected += fmt::format("{}{}", expected.empty() ? "" : ", ", name);
  throw evaluator::InputError(fmt::format("unknown {} state '{}' (expected one of {})", what, text, expected));
}

}  // namespace

std::string_view ToString(QueuedRunState state) { return NameOf(kRunNames, state); }
std::string_view ToString(QueuedSweepState state) { return NameOf(kSweepNames, state); }
std::string_view ToString(ReportState state) { return NameOf(kReportNames, state); }

std::optional<QueuedRunState> FindRunState(std::string_view text) { return StateNamed(kRunNames, text); }
std::optional<QueuedSweepState> FindSweepState(std::string_view text) { return StateNamed(kSweepNames, text); }
std::optional<ReportState> FindReportState(std::string_view text) { return StateNamed(kReportNames, text); }

QueuedRunState ParseRunState(std::string_view text) { return ParseState(kRunNames, text, "run"); }
QueuedSweepState ParseSweepState(std::string_view text) { return ParseState(kSweepNames, text, "sweep"); }

std::string_view CancellingStateName() { return "cancelling"; }

bool IsFinished(QueuedSweepState state) {
  return state == QueuedSweepState::kOk || state == QueuedSweepState::kFailed || state == QueuedSweepState::kCancelled;
}

bool HasResult(QueuedRunState state) {
  return state == QueuedRunState::kOk || state == QueuedRunState::kFailed || state == QueuedRunState::kReused;
}

bool IsUnfinished(QueuedRunState state) {
  return state == QueuedRunState::kQueued || state == QueuedRunState::kRunning;
}

}  // namespace slamsweep::orchestrator::inline run
