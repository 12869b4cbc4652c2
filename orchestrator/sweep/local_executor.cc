#include "orchestrator/sweep/local_executor.h"

#include <cstdlib>
#include <utility>

#include "orchestrator/phase_times/phase_times.h"
#include "orchestrator/sweep/worker_environment.h"
#include "orchestrator/worker/worker.h"

namespace slamsweep::orchestrator::inline sweep {

LocalExecutor::LocalExecutor(std::filesystem::path worker_program) : worker_program_(std::move(worker_program)) {}

void LocalExecutor::Start(const RunSpec& run, const std::filesystem::path& run_dir) {
  ProcessSpec spec;
  spec.argv = {worker_program_.string(), "worker", run_dir.string()};
  spec.extra_env = WorkerEnvironment();
  spec.log_path = run_dir / "worker.log";
  spec.log_cap_bytes = kWorkerLogCapBytes;
  spec.timeout_s = run.algorithm.timeout_s + kWorkerOverheadS;
  // The worker forwards SIGTERM to its program and removes partial outputs: give it time to.
  spec.grace_s = 10.0;
  run_ids_[processes_.Start(spec)] = run.run_id;
}

std::vector<WorkerEnding> LocalExecutor::Endings(const std::vector<std::pair<ProcessSet::Id, ProcessOutcome>>& ended) {
  std::vector<WorkerEnding> endings;
  for (const auto& [id, outcome] : ended) {
    const auto found = run_ids_.find(id);
    if (found == run_ids_.end()) continue;
    // The worker process as a whole (start-up included), beside the phases it times itself.
    AddPhaseTime("worker_process", outcome.wall_s, outcome.cpu_s);
    WorkerEnding ending;
    ending.run_id = found->second;
    ending.interrupted = outcome.ending == ProcessEnding::kInterrupted ||
                         (outcome.ending == ProcessEnding::kExited && outcome.exit_code == 130);
    ending.reason = "worker: " + outcome.reason;
    endings.push_back(std::move(ending));
    run_ids_.erase(found);
  }
  return endings;
}

std::vector<WorkerEnding> LocalExecutor::Wait() { return Endings(processes_.WaitForAny()); }

std::vector<WorkerEnding> LocalExecutor::TerminateAll() { return Endings(processes_.TerminateAll()); }

void LocalExecutor::Stop(const std::string& run_id) {
  for (const auto& [id, running_id] : run_ids_) {
    if (running_id == run_id) processes_.Stop(id);
  }
}

bool LocalExecutor::Interrupted() const { return InterruptionGuard::Interrupted(); }

std::filesystem::path WorkerProgram() {
  const char* configured = std::getenv("SLAMSWEEP_WORKER_PROGRAM");
  if (configured != nullptr && *configured != '\0') return configured;
  return std::filesystem::read_symlink("/proc/self/exe");
}

}  // namespace slamsweep::orchestrator::inline sweep
