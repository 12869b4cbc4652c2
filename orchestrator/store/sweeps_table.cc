#include "orchestrator/store/sweeps_table.h"

#include <optional>
#include <utility>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/store/utc_now.h"

namespace slamsweep::orchestrator::inline store {

using evaluator::InputError;

std::int64_t InsertSweep(SqliteDb& db, const SweepInfo& info) {
  SqliteTransaction transaction(db);
  auto insert = db.Prepare(
      "INSERT INTO sweeps(name, config_path, config_sha, started_at, status, host, slamsweep_version, run_count, "
      "command_line) VALUES(?, ?, ?, ?, ?, ?, ?, 0, ?)");
  insert.Bind(1, info.name).Bind(2, info.config_path).Bind(3, info.config_sha);
  insert.Bind(4, info.started_at.empty() ? UtcNowIso8601() : info.started_at);
  insert.Bind(5, SweepStatusName(SweepStatus::kRunning));
  insert.Bind(6, info.host).Bind(7, info.slamsweep_version).Bind(8, info.command_line);
  insert.Run();
  const std::int64_t id = db.LastInsertRowId();
  transaction.Commit();
  return id;
}

void MarkSweepFinished(SqliteDb& db, std::int64_t sweep_id, SweepStatus status, std::int64_t run_count) {
  SqliteTransaction transaction(db);
  auto update = db.Prepare("UPDATE sweeps SET finished_at = ?, status = ?, run_count = ? WHERE id = ?");
  update.Bind(1, UtcNowIso8601()).Bind(2, SweepStatusName(status)).Bind(3, run_count).Bind(4, sweep_id);
  update.Run();
  transaction.Commit();
}

std::vector<StoredSweep> ReadSweeps(const SqliteDb& db) {
  auto select = db.Prepare(
      "SELECT id, name, config_path, config_sha, started_at, finished_at, status, host, slamsweep_version, "
      "run_count, command_line FROM sweeps ORDER BY id");
  std::vector<StoredSweep> sweeps;
  while (select.Step()) {
    StoredSweep s;
    s.id = select.Int64(0);
    s.info.name = select.TextOrEmpty(1);
    s.info.config_path = select.TextOrEmpty(2);
    s.info.config_sha = select.TextOrEmpty(3);
    s.info.started_at = select.TextOrEmpty(4);
    s.finished_at = select.TextOrEmpty(5);
    const std::string status = select.TextOrEmpty(6);
    const std::optional<SweepStatus> known = SweepStatusFromName(status);
    if (!known) {
      throw InputError(
          fmt::format("{}: sweeps.status of sweep {}: expected running, ok, failed or interrupted, found \"{}\"",
                      db.file().string(), s.id, status));
    }
    s.status = *known;
    s.info.host = select.TextOrEmpty(7);
    s.info.slamsweep_version = select.TextOrEmpty(8);
    s.run_count = select.Int64(9);
    s.info.command_line = select.TextOrEmpty(10);
    sweeps.push_back(std::move(s));
  }
  return sweeps;
}

std::int64_t FindOrInsertSweep(SqliteDb& db, const StoredSweep& sweep) {
  SqliteTransaction transaction(db);
  auto find =
      db.Prepare("SELECT id FROM sweeps WHERE name IS ? AND config_sha IS ? AND started_at IS ? AND host IS ? LIMIT 1");
  find.Bind(1, sweep.info.name).Bind(2, sweep.info.config_sha).Bind(3, sweep.info.started_at);
  find.Bind(4, sweep.info.host);
  if (find.Step()) {
    const std::int64_t id = find.Int64(0);
    transaction.Commit();
    return id;
  }
  auto insert = db.Prepare(
      "INSERT INTO sweeps(name, config_path, config_sha, started_at, finished_at, status, host, slamsweep_version, "
      "run_count, command_line) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  insert.Bind(1, sweep.info.name).Bind(2, sweep.info.config_path).Bind(3, sweep.info.config_sha);
  insert.Bind(4, sweep.info.started_at).Bind(5, sweep.finished_at).Bind(6, SweepStatusName(sweep.status));
  insert.Bind(7, sweep.info.host).Bind(8, sweep.info.slamsweep_version).Bind(9, sweep.run_count);
  insert.Bind(10, sweep.info.command_line);
  insert.Run();
  const std::int64_t id = db.LastInsertRowId();
  transaction.Commit();
  return id;
}

}  // namespace slamsweep::orchestrator::inline store
