#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "orchestrator/run/run_json.h"
#include "orchestrator/supervisor/executor.h"
#include "orchestrator/sweep/status.h"
#include "orchestrator/run/run_status.h"

namespace slamsweep::orchestrator::inline sweep {

/// Everything about a sweep that is not a run.
struct SweepSettings {
  std::string name;
  std::filesystem::path output_dir;
  /// Runs at once (>= 1).
  std::size_t jobs = 1;
  /// Stop starting runs after this many failures in this sweep; 0 = never (keep going).
  std::size_t failure_budget = 0;
  /// Start runs that an earlier sweep recorded as failed again (`--rerun failed`).
  bool rerun_failed = false;
  /// Reuse finished runs whose build identity (slamsweep revision, program digests) differs from
  /// the run's now (`--reuse-stale`); by default they are run again.
  bool reuse_stale = false;
  /// The validity study the sweep file names (validity_study:), copied into the output directory
  /// for the report (orchestrator/store/named_study.h); empty when none.
  std::filesystem::path validity_study;
  /// Recorded with the sweep, to reproduce it.
  std::string config_path;
  std::string config_sha;
  std::string command_line;
};

struct SweepOutcome {
  std::size_t total = 0;
  std::size_t ok = 0;
  std::size_t failed = 0;
  /// Finished by an earlier sweep and not run again.
  std::size_t already_done = 0;
  /// Finished by an earlier sweep under another build identity or evaluation: run again (or, with reuse_stale,
  /// counted in already_done too).
  std::size_t stale = 0;
  /// Never started: the failure budget ran out or the sweep was interrupted.
  std::size_t not_started = 0;
  bool interrupted = false;

  /// 0 every run ok, 1 some run failed or was not started, 130 interrupted.
  int ExitCode() const;
};

/// Runs `runs` (one sweep's matrix, or a shard of it) into settings.output_dir: takes the
/// directory's lock, skips runs the results store already holds under the same build identity
/// (RecordedRunIsReusable; and adopts finished result.json
/// files the store missed, e.g. after the orchestrator was killed), starts the rest
/// longest-expected-first through `executor` with at most `jobs` at once, records each result
/// the moment it ends, and writes summary.json and junit.xml at the end, also when interrupted.
/// A failing run is data, never an exception; exceptions mean the sweep itself cannot go on
/// (unwritable output directory, locked directory, corrupt store).
SweepOutcome RunSweep(const std::vector<RunSpec>& runs, const SweepSettings& settings, Executor& executor,
                      Status& status);

/// Whether a recorded run (its run.json as recorded) may stand for `run`: it finished ("ok", or
/// "failed" unless rerun_failed) and was computed under the same build identity and scored under
/// the same evaluation options (SameEvaluation), or reuse_stale. `stale` is set when only the build
/// identity or the evaluation options stood in the way (or were waived by reuse_stale).
bool RecordedRunIsReusable(const RunSpec& run, std::optional<RunStatus> recorded_status,
                           const nlohmann::json& recorded_spec, const SweepSettings& settings, bool& stale);

/// Order in which runs start: longest expected first (durations recorded by earlier sweeps,
/// keyed "<algorithm>\t<sequence>"), so that a long run does not start last and stretch the
/// makespan; runs without history count as the longest known. Stable for equal expectations.
std::vector<const RunSpec*> LongestExpectedFirst(const std::vector<const RunSpec*>& runs,
                                                 const std::map<std::string, double>& typical_wall_s);

}  // namespace slamsweep::orchestrator::inline sweep
