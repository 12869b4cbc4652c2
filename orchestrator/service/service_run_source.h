#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "orchestrator/service/fair_share.h"
#include "orchestrator/service/service_metrics.h"
#include "orchestrator/service/sweep_entry.h"
#include "orchestrator/service/sweep_table.h"
#include "orchestrator/supervisor/run_source.h"

namespace slamsweep::orchestrator::service {

/// The service's queue for the Supervisor: every active sweep's runs, started in fair shares
/// (fair_share.h), reused from an identical ok twin when one exists (run_reuse.h), each ending
/// recorded in its sweep's result directory and in the queue. Between starts it activates waiting
/// sweeps, stops cancelled ones and finishes the complete ones (sweep_lifecycle.h). It never runs
/// dry: new sweeps may be submitted at any time, so only a drain ends the loop.
class ServiceRunSource final : public RunSource {
 public:
  /// `draining`: the scheduler's flag, set by Drain() from any thread and here when an
  /// interruption is noticed. `max_attempts`: how often a run interrupted from outside is queued
  /// again before it is recorded as failed. `drain_grace_s` is only named in the drain's log line.
  ServiceRunSource(SweepTable& sweeps, const std::filesystem::path& data_dir, std::atomic<bool>& draining,
                   int max_attempts, double drain_grace_s, ServiceMetrics& metrics);

  std::optional<RunStart> Next() override;
  void Started(const RunStart& start) override;
  bool StartFailed(const std::exception& error) override;
  void Ended(const WorkerEnding& ending) override;
  bool AwaitsMore() const override { return true; }
  bool DrainRequested() const override { return draining_.load(); }
  void BeginTurn(Executor& executor) override;
  void EndTurn() override;
  void Draining() override;
  void Terminating(std::size_t running) override;

 private:
  using Clock = std::chrono::steady_clock;

  void ActivateWaitingSweeps();
  void HandleCancels(Executor& executor);
  void RecordStartFailure(SweepEntry& entry, std::size_t index, const std::exception& error);

  SweepTable& sweeps_;
  std::filesystem::path data_dir_;
  std::atomic<bool>& draining_;
  int max_attempts_;
  double drain_grace_s_;
  ServiceMetrics& metrics_;

  RunningRuns running_;
  std::uint64_t tick_ = 0;
  /// The run the last Next() gave, and when choosing it began (scheduling latency).
  SweepEntry* next_entry_ = nullptr;
  std::size_t next_index_ = 0;
  Clock::time_point next_chosen_from_;
  /// Slots freed by ended runs and not yet taken, each with when it was freed (scheduling latency).
  std::vector<std::pair<std::string, Clock::time_point>> slot_freed_;
};

}  // namespace slamsweep::orchestrator::service
