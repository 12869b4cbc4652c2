#pragma once

#include <filesystem>
#include <string>

#include "orchestrator/run/run_status.h"
#include "orchestrator/service/sweep_entry.h"
#include "orchestrator/service/sweep_table.h"

namespace slamsweep::orchestrator::service {

// A sweep's start and end on the scheduler thread: its result directory is opened and closed with the
// same steps as `slamsweep run`'s output directory (orchestrator/sweep/sweep_steps.h), so report,
// merge and history read it as they read a run's.

/// Opens `entry`'s result directory (lock, results.sqlite, a sweep row) and lists its unfinished runs
/// as pending, except those the directory already holds (a server killed after recording them, before
/// its queue said so): those count as done, as in the rerun-skip check of `slamsweep run`. Then the
/// sweep is running. False, with the sweep failed, when the directory cannot be opened.
bool ActivateSweep(SweepTable& sweeps, SweepEntry& entry, const std::filesystem::path& data_dir);

/// Writes the ended sweep's outputs (summaries, JUnit) into its result directory, closes it and records
/// the sweep ended: `state` kCancelled stays, anything else becomes kOk or kFailed by its runs. Its
/// report is then to be written. The sweep fails when its outputs cannot be written.
void FinishSweep(SweepTable& sweeps, SweepEntry& entry, QueuedSweepState state, const std::string& message);

/// Ends a sweep that cannot go on: its queued runs cancelled, the sweep failed with `message`, no report.
void FailSweep(SweepTable& sweeps, SweepEntry& entry, const std::string& message);

}  // namespace slamsweep::orchestrator::service
