#pragma once

#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/run/run_spec.h"
#include "orchestrator/run/run_status.h"
#include "orchestrator/service/queue_store.h"
#include "orchestrator/service/sweep_entry.h"
#include "orchestrator/service/sweep_views.h"

namespace slamsweep::orchestrator::service {

/// What a cancel request found.
struct CancelOutcome {
  /// False: there is no such sweep.
  bool known = false;
  /// The sweep's own state when it had finished already; nullopt when it is now being cancelled.
  std::optional<QueuedSweepState> finished_as;
};

/// Every sweep the server knows, shared by the scheduler thread and the HTTP threads: each change is
/// written to the durable queue (DATA/queue.sqlite) first and then shown to readers. Readers get
/// copies (views) under the table's lock. Only the scheduler thread changes entries; it reads them
/// without the lock and takes it only to change what readers see. Sweeps are never removed, so an
/// entry's address stays valid for the table's life.
class SweepTable {
 public:
  /// `slots`: the pool's worker slots, for the ETA of the views.
  SweepTable(QueueStore& queue, std::mutex& queue_mutex, std::filesystem::path sweeps_root, std::size_t slots);
  ~SweepTable();

  /// Loads the queue after a (re)start: runs left running are queued again, and finished sweeps whose
  /// report is missing are queued for one. Call before any other member.
  void Load();
  /// Queues a sweep and its runs durably, then shows it; returns it with its id and result directory.
  QueuedSweep Add(QueuedSweep sweep, const std::vector<RunSpec>& runs);
  /// Records that the sweep is to be cancelled, unless it finished already.
  CancelOutcome RequestCancel(std::int64_t sweep_id);

  std::vector<SweepView> Sweeps() const;
  std::optional<SweepView> Sweep(std::int64_t id) const;
  std::optional<std::vector<RunView>> Runs(std::int64_t sweep_id) const;
  /// Sweeps not finished (queued or running).
  std::size_t UnfinishedSweeps() const;

  /// The oldest sweep whose report is to be written, taken off the list of report jobs.
  std::optional<QueuedSweep> TakeReportJob();
  void ReportWritten(std::int64_t sweep_id, bool ok);

  // The scheduler thread's side.

  /// The sweeps for which `wanted` holds, chosen under the lock.
  std::vector<SweepEntry*> Select(const std::function<bool(const SweepEntry&)>& wanted);
  SweepEntry& Entry(std::int64_t id);
  /// Sweep `id`'s result directory; nullopt for an unknown sweep.
  std::optional<std::filesystem::path> ResultDir(std::int64_t id) const;
  /// QueueStore::SweepsWithOkRun.
  std::vector<std::int64_t> SweepsWithOkRun(const std::string& run_id, std::int64_t except_sweep) const;

  /// Records run `index` of `entry` in its new state; `attempt_started` counts one more attempt.
  void SetRunState(SweepEntry& entry, std::size_t index, QueuedRunState state, bool attempt_started,
                   std::optional<double> wall_s, const std::string& reason,
                   std::optional<std::int64_t> reused_from = std::nullopt);
  /// Records `entry` running (in the queue only when it was queued there) and active from now.
  void MarkStarted(SweepEntry& entry);
  /// Records `entry`'s final state in the queue; ShowEnded then shows it.
  void RecordEnded(const SweepEntry& entry, QueuedSweepState state, const std::string& message);
  /// Shows `entry` ended (no longer active) with its report in `report`; kWriting makes it a report job.
  void ShowEnded(SweepEntry& entry, QueuedSweepState state, const std::string& message, ReportState report);
  /// Counts one more run of `entry` ended with a result.
  void CountFinished(SweepEntry& entry);
  /// Closes every sweep's result directory; unfinished sweeps stay running in the queue, for the next server.
  void CloseAll();

 private:
  QueueStore& queue_;
  std::mutex& queue_mutex_;
  std::filesystem::path sweeps_root_;
  std::size_t slots_;

  mutable std::mutex mutex_;  // guards sweeps_, report_jobs_ and what readers see of each entry
  std::map<std::int64_t, std::unique_ptr<SweepEntry>> sweeps_;
  std::deque<std::int64_t> report_jobs_;
};

}  // namespace slamsweep::orchestrator::service
