#pragma once

#include <cstddef>
#include <exception>
#include <filesystem>
#include <optional>

#include "orchestrator/run/run_spec.h"
#include "orchestrator/supervisor/executor.h"

namespace slamsweep::orchestrator::inline supervisor {

/// A run the source wants started now; its folder is ready (run.json written).
struct RunStart {
  const RunSpec* run = nullptr;
  std::filesystem::path run_dir;
};

/// What the Supervisor runs: one sweep's queue (`slamsweep run`) or the service's shared queue. The
/// source decides which run starts next and takes each ending; the supervisor decides when to ask,
/// when to wait and how to drain. Every call comes from the supervisor's thread.
class RunSource {
 public:
  virtual ~RunSource() = default;

  /// The run to start now, or nullopt when none may start (queue empty, failure budget spent, no
  /// fair share left, draining). Asked only while a slot is free and no interruption arrived.
  virtual std::optional<RunStart> Next() = 0;
  /// The executor took the run the last Next() gave.
  virtual void Started(const RunStart& start) = 0;
  /// The executor's Start threw for the run the last Next() gave: true when the source recorded
  /// it and the loop goes on; false lets the error end the loop.
  virtual bool StartFailed(const std::exception& /*error*/) { return false; }
  /// A started run ended: by itself, stopped, or terminated by a drain.
  virtual void Ended(const WorkerEnding& ending) = 0;

  /// True when runs may still arrive although none runs and none may start (the service's queue
  /// takes submissions): the loop then sleeps until woken instead of ending.
  virtual bool AwaitsMore() const { return false; }
  /// True when the source asks for a drain without an interruption (the service's Drain()).
  virtual bool DrainRequested() const { return false; }

  /// Each turn, before runs start (the service activates waiting sweeps and stops cancelled runs).
  virtual void BeginTurn(Executor& /*executor*/) {}
  /// Each turn after runs started, and once more after a drain's terminations (the service
  /// finishes the sweeps that are complete).
  virtual void EndTurn() {}
  /// The loop noticed an interruption or a drain request, once: nothing starts from now on.
  virtual void Draining() {}
  /// The drain's grace period is over: the `running` runs left are terminated now.
  virtual void Terminating(std::size_t /*running*/) {}
};

}  // namespace slamsweep::orchestrator::inline supervisor
