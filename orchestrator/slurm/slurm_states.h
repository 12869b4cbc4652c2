#pragma once

#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace slamsweep::orchestrator::inline slurm {

/// One array task as Slurm reports it.
struct SlurmTaskState {
  int task_id = 0;
  /// Slurm's state name without decoration: "PENDING", "RUNNING", "COMPLETED", "FAILED", "TIMEOUT",
  /// "OUT_OF_MEMORY", "CANCELLED", "NODE_FAIL", ...
  std::string state;
  /// Exit code of the batch script (the worker); -1 when unknown.
  int exit_code = -1;
  /// The signal that ended the batch script, 0 if none.
  int signal = 0;
};

/// Task ids of an ArrayTaskId field: "7", "2-5", "2-5%4", "1,3,5-7" (a pending remainder).
/// Empty set for text it cannot read.
std::set<int> ParseArrayTaskIds(std::string_view text);

/// Reads `scontrol show job -o JOB` output (one record per line; pending tasks share one record
/// whose ArrayTaskId is a range). Records without ArrayTaskId are ignored.
std::vector<SlurmTaskState> ParseScontrolJobs(std::string_view text);

/// Reads `sacct -j JOB --array -n -P -o JobID,State,ExitCode` output ("12_3|FAILED|3:0"; step lines
/// "12_3.batch" are skipped, "12_[4-9]" pending ranges expand, "CANCELLED by 0" becomes CANCELLED).
std::vector<SlurmTaskState> ParseSacct(std::string_view text);

/// True for the states in which a task no longer runs and never will again.
bool IsFinalState(std::string_view state);

/// What a finished task means for the run when the worker left no result.json.
struct SlurmTaskEnding {
  /// One sentence: "Slurm TIMEOUT (--time limit)", "Slurm FAILED: worker exit code 2", ...
  std::string reason;
  /// Cancelled on our own request (the sweep was interrupted): not a result of the run.
  bool interrupted = false;
};

/// Maps a final task state onto the run's failure reason. `cancelled_by_us`: the executor itself
/// called scancel (TerminateAll), so CANCELLED means "interrupted", not a failure.
SlurmTaskEnding EndingForState(const SlurmTaskState& task, bool cancelled_by_us);

}  // namespace slamsweep::orchestrator::inline slurm
