#include "orchestrator/service/scheduler.h"

#include <spdlog/spdlog.h>

#include "orchestrator/process/wake_up.h"
#include "orchestrator/service/service_run_source.h"
#include "orchestrator/supervisor/supervisor.h"

namespace slamsweep::orchestrator::service {

Scheduler::Scheduler(QueueStore& queue, std::mutex& queue_mutex, const std::filesystem::path& data_dir,
                     SchedulerOptions options, ServiceMetrics& metrics)
    : data_dir_(data_dir),
      options_(options),
      metrics_(metrics),
      sweeps_(queue, queue_mutex, data_dir / "sweeps", options.jobs) {}

Scheduler::~Scheduler() = default;

void Scheduler::Recover() { sweeps_.Load(); }

QueuedSweep Scheduler::Submit(QueuedSweep sweep, const std::vector<RunSpec>& runs) {
  sweep = sweeps_.Add(std::move(sweep), runs);
  spdlog::info("sweep {} '{}' submitted by {}: {} runs, priority {}", sweep.id, sweep.name, sweep.submitter,
               runs.size(), sweep.priority);
  RequestWakeUp();
  return sweep;
}

CancelOutcome Scheduler::Cancel(std::int64_t sweep_id) {
  const CancelOutcome outcome = sweeps_.RequestCancel(sweep_id);
  if (!outcome.known || outcome.finished_as) return outcome;
  spdlog::info("sweep {}: cancel requested", sweep_id);
  RequestWakeUp();
  return outcome;
}

void Scheduler::Drain() {
  draining_ = true;
  RequestWakeUp();
}

void Scheduler::Run(Executor& executor) {
  ServiceRunSource source(sweeps_, data_dir_, draining_, options_.max_attempts, options_.drain_grace_s, metrics_);
  Supervisor(executor, {.jobs = options_.jobs, .drain_grace_s = options_.drain_grace_s, .time_phases = false})
      .Run(source);
  sweeps_.CloseAll();
}

}  // namespace slamsweep::orchestrator::service
