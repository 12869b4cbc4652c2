#include "orchestrator/process/process_outcome.h"

namespace slamsweep::orchestrator::inline process {

std::string_view EndingName(ProcessEnding ending) {
  switch (ending) {
    case ProcessEnding::kExited:
      return "exited";
    case ProcessEnding::kSignaled:
      return "signaled";
    case ProcessEnding::kTimedOut:
      return "timed_out";
    case ProcessEnding::kMemoryLimit:
      return "memory_limit";
    case ProcessEnding::kProcessLimit:
      return "process_limit";
    case ProcessEnding::kInterrupted:
      return "interrupted";
    case ProcessEnding::kFailedToStart:
      return "failed_to_start";
  }
  return "unknown";
}

}  // namespace slamsweep::orchestrator::inline process
