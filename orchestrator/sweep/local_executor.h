#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "orchestrator/process/process_set.h"
#include "orchestrator/supervisor/executor.h"

namespace slamsweep::orchestrator::inline sweep {

/// Runs each run as `WORKER_PROGRAM worker RUN_DIR` on this machine, several at once.
class LocalExecutor final : public Executor {
 public:
  /// `worker_program`: the slamsweep binary (the running one, normally).
  explicit LocalExecutor(std::filesystem::path worker_program);

  void Start(const RunSpec& run, const std::filesystem::path& run_dir) override;
  std::vector<WorkerEnding> Wait() override;
  std::vector<WorkerEnding> TerminateAll() override;
  void Stop(const std::string& run_id) override;
  std::size_t Running() const override { return processes_.running(); }
  bool Interrupted() const override;

  /// Time a worker gets beyond its program's timeout: reading the sequence, writing the input,
  /// scoring and writing outputs. The program's own timeout is enforced inside the worker, so
  /// this only catches a worker that itself hangs.
  static constexpr double kWorkerOverheadS = 600.0;

 private:
  std::vector<WorkerEnding> Endings(const std::vector<std::pair<ProcessSet::Id, ProcessOutcome>>& ended);

  std::filesystem::path worker_program_;
  ProcessSet processes_;
  std::map<ProcessSet::Id, std::string> run_ids_;
};

/// The program started as `PROGRAM worker RUN_DIR`: $SLAMSWEEP_WORKER_PROGRAM when set (tests that
/// run the command line inside a test binary, installations that split the binaries), else this
/// program's own executable (/proc/self/exe).
std::filesystem::path WorkerProgram();

}  // namespace slamsweep::orchestrator::inline sweep
