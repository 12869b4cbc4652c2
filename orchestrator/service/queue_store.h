#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "orchestrator/run/run_status.h"
#include "orchestrator/store/sqlite_db.h"

namespace slamsweep::orchestrator::service {

/// A sweep as submitted and as it stands.
struct QueuedSweep {
  std::int64_t id = 0;
  std::string name;
  /// The file name the submitter gave (messages name it) and the submitted YAML text.
  std::string config_name;
  std::string config_text;
  std::string submitter;
  int priority = 0;
  QueuedSweepState state = QueuedSweepState::kQueued;
  /// The sweep's result directory (the layout of `slamsweep run`'s output directory).
  std::filesystem::path result_dir;
  std::string submitted_at, started_at, finished_at;
  bool cancel_requested = false;
  /// Why a sweep could not go on (its result directory could not be opened, ...); empty normally.
  std::string message;
};

/// One run of a queued sweep.
struct QueuedRun {
  std::int64_t sweep_id = 0;
  std::string run_id;
  /// Position in the sweep's start order.
  std::int64_t position = 0;
  QueuedRunState state = QueuedRunState::kQueued;
  /// How many times a worker was started for it.
  int attempt = 0;
  /// The sweep whose identical ok run this one reuses (reused runs only).
  std::optional<std::int64_t> reused_from;
  std::optional<double> wall_s;
  std::string reason;
  /// run.json as planned at submission (RunSpec).
  nlohmann::json spec;
};

/// DATA/queue.sqlite: every submitted sweep (its YAML text, submitter, priority, state) and every run
/// (state, attempt). The durable half of the service: after a kill -9 the server rebuilds its queue
/// from here (runs found running are queued again). A state name it cannot read is an InputError. WAL journal, one
/// immediate transaction per change, so a kill at any moment leaves the old or the new state. Not thread-safe: one user
/// at a time.
class QueueStore {
 public:
  static QueueStore Open(const std::filesystem::path& file);

  /// Adds a sweep and its runs (state queued) in one transaction and returns it with its new id and
  /// its result directory `sweeps_root`/<id>. `runs` are run.json objects in start order.
  QueuedSweep AddSweep(QueuedSweep sweep, const std::vector<nlohmann::json>& runs,
                       const std::filesystem::path& sweeps_root);

  std::vector<QueuedSweep> Sweeps() const;
  std::optional<QueuedSweep> Sweep(std::int64_t id) const;
  std::vector<QueuedRun> Runs(std::int64_t sweep_id) const;

  void SetSweepState(std::int64_t id, QueuedSweepState state, const std::string& message = {});
  void RequestCancel(std::int64_t id);

  /// Records a run's new state; `attempt_started` counts one more attempt (a worker was started).
  void SetRunState(std::int64_t sweep_id, const std::string& run_id, QueuedRunState state, bool attempt_started = false,
                   std::optional<double> wall_s = std::nullopt, const std::string& reason = {},
                   std::optional<std::int64_t> reused_from = std::nullopt);

  /// After a restart: every run left running by a server that died is queued again. Returns how many.
  std::size_t RequeueRunning();

  /// Sweeps (other than `except_sweep`) holding `run_id` as ok or reused, newest first.
  std::vector<std::int64_t> SweepsWithOkRun(const std::string& run_id, std::int64_t except_sweep) const;

 private:
  explicit QueueStore(SqliteDb db) : db_(std::move(db)) {}
  SqliteDb db_;
};

}  // namespace slamsweep::orchestrator::service
