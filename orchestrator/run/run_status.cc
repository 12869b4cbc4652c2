#include "orchestrator/run/run_status.h"

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

}  // namespace slamsweep::orchestrator::inline run
