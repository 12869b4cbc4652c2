#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace slamsweep::orchestrator::inline run {

/// Why a run failed, as result.json's `failure_kind` names it (orchestrator/DESIGN.md).
enum class FailureKind {
  kTimeout,
  kSignal,
  kExitCode,
  kMissingOutput,
  kCorruptOutput,
  kIncompleteTrajectory,  ///< the trajectory spans too little of the reference's time (evaluation.min_coverage)
  kInputError,
  kMemoryLimit,
  kProcessLimit,
  kDiskLimit,
  kNotIsolated,
  kInterrupted,
  kInternal,
};

/// "timeout", "signal", "exit_code", "missing_output", "corrupt_output", "incomplete_trajectory",
/// "input_error", "memory_limit", "process_limit", "disk_limit", "not_isolated", "interrupted", "internal".
std::string_view FailureKindName(FailureKind kind);

/// A failure of one run that an adapter detects (an output missing or unreadable). The worker
/// records it as data in result.json; it never ends a sweep.
class RunFailure : public std::runtime_error {
 public:
  RunFailure(FailureKind kind, const std::string& reason) : std::runtime_error(reason), kind_(kind) {}
  FailureKind kind() const { return kind_; }

 private:
  FailureKind kind_;
};

}  // namespace slamsweep::orchestrator::inline run
