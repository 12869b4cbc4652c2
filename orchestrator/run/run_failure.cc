#include "orchestrator/run/run_failure.h"

namespace slamsweep::orchestrator::inline run {

std::string_view FailureKindName(FailureKind kind) {
  switch (kind) {
    case FailureKind::kTimeout:
      return "timeout";
    case FailureKind::kSignal:
      return "signal";
    case FailureKind::kExitCode:
      return "exit_code";
    case FailureKind::kMissingOutput:
      return "missing_output";
    case FailureKind::kCorruptOutput:
      return "corrupt_output";
    case FailureKind::kIncompleteTrajectory:
      return "incomplete_trajectory";
    case FailureKind::kInputError:
      return "input_error";
    case FailureKind::kMemoryLimit:
      return "memory_limit";
    case FailureKind::kProcessLimit:
      return "process_limit";
    case FailureKind::kDiskLimit:
      return "disk_limit";
    case FailureKind::kNotIsolated:
      return "not_isolated";
    case FailureKind::kInterrupted:
      return "interrupted";
    case FailureKind::kInternal:
      return "internal";
  }
  return "internal";
}

}  // namespace slamsweep::orchestrator::inline run
