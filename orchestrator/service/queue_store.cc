#include "orchestrator/service/queue_store.h"

#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator::service {
namespace {

constexpr int kQueueSchemaVersion = 1;

constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS sweeps (
  id INTEGER PRIMARY KEY,
  name TEXT NOT NULL,
  config_name TEXT NOT NULL,
  config_text TEXT NOT NULL,
  submitter TEXT NOT NULL,
  priority INTEGER NOT NULL,
  state TEXT NOT NULL,
  result_dir TEXT NOT NULL,
  submitted_at TEXT NOT NULL,
  started_at TEXT NOT NULL DEFAULT '',
  finished_at TEXT NOT NULL DEFAULT '',
  cancel_requested INTEGER NOT NULL DEFAULT 0,
  message TEXT NOT NULL DEFAULT ''
);
CREATE TABLE IF NOT EXISTS runs (
  sweep_id INTEGER NOT NULL REFERENCES sweeps(id),
  run_id TEXT NOT NULL,
  position INTEGER NOT NULL,
  state TEXT NOT NULL,
  attempt INTEGER NOT NULL DEFAULT 0,
  reused_from INTEGER,
  wall_s REAL,
  reason TEXT NOT NULL DEFAULT '',
  spec TEXT NOT NULL,
  PRIMARY KEY (sweep_id, run_id)
);
CREATE INDEX IF NOT EXISTS runs_by_run_id ON runs(run_id, state);
)sql";

QueuedSweep SweepFromRow(const SqliteStatement& row) {
  QueuedSweep sweep;
  sweep.id = row.Int64(0);
  sweep.name = row.Text(1);
  sweep.config_name = row.Text(2);
  sweep.config_text = row.Text(3);
  sweep.submitter = row.Text(4);
  sweep.priority = static_cast<int>(row.Int64(5));
  sweep.state = ParseSweepState(row.Text(6));
  sweep.result_dir = row.Text(7);
  sweep.submitted_at = row.Text(8);
  sweep.started_at = row.Text(9);
  sweep.finished_at = row.Text(10);
  sweep.cancel_requested = row.Int64(11) != 0;
  sweep.message = row.Text(12);
  return sweep;
}

constexpr const char* kSweepColumns =
    "SELECT id, name, config_name, config_text, submitter, priority, state, result_dir, submitted_at, started_at, "
    "finished_at, cancel_requested, message FROM sweeps";

}  // namespace

QueueStore QueueStore::Open(const std::filesystem::path& file) {
  std::filesystem::create_directories(file.parent_path());
  SqliteDb db = SqliteDb::Open(file, /*create=*/true);
  db.Execute("PRAGMA journal_mode = WAL");
  db.Execute("PRAGMA synchronous = NORMAL");
  db.Execute("PRAGMA foreign_keys = ON");
  db.Execute(kSchema);
  db.Execute("PRAGMA user_version = " + std::to_string(kQueueSchemaVersion));
  return QueueStore(std::move(db));
}

QueuedSweep QueueStore::AddSweep(QueuedSweep sweep, const std::vector<nlohmann::json>& runs,
                                 const std::filesystem::path& sweeps_root) {
  SqliteTransaction transaction(db_);
  {
    // Inside the write transaction, so two submissions never get one id.
    auto next = db_.Prepare("SELECT COALESCE(MAX(id), 0) + 1 FROM sweeps");
    next.Step();
    sweep.id = next.Int64(0);
  }
  sweep.result_dir = sweeps_root / std::to_string(sweep.id);
  sweep.state = QueuedSweepState::kQueued;
  sweep.submitted_at = UtcNowIso8601();
  auto insert = db_.Prepare(
      "INSERT INTO sweeps (id, name, config_name, config_text, submitter, priority, state, result_dir, submitted_at) "
      "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)");
  insert.Bind(1, sweep.id)
      .Bind(2, std::string_view(sweep.name))
      .Bind(3, std::string_view(sweep.config_name))
      .Bind(4, std::string_view(sweep.config_text))
      .Bind(5, std::string_view(sweep.submitter))
      .Bind(6, static_cast<std::int64_t>(sweep.priority))
      .Bind(7, ToString(sweep.state))
      .Bind(8, std::string_view(sweep.result_dir.string()))
      .Bind(9, std::string_view(sweep.submitted_at));
  insert.Run();
  auto add_run = db_.Prepare("INSERT INTO runs (sweep_id, run_id, position, state, spec) VALUES (?, ?, ?, ?, ?)");
  std::int64_t position = 0;
  for (const nlohmann::json& run : runs) {
    add_run.Reset();
    add_run.Bind(1, sweep.id)
        .Bind(2, std::string_view(run.at("run_id").get_ref<const std::string&>()))
        .Bind(3, position++)
        .Bind(4, ToString(QueuedRunState::kQueued))
        .Bind(5, std::string_view(run.dump()));
    add_run.Run();
  }
  transaction.Commit();
  return sweep;
}

std::vector<QueuedSweep> QueueStore::Sweeps() const {
  std::vector<QueuedSweep> sweeps;
  auto query = db_.Prepare(std::string(kSweepColumns) + " ORDER BY id");
  while (query.Step()) sweeps.push_back(SweepFromRow(query));
  return sweeps;
}

std::optional<QueuedSweep> QueueStore::Sweep(std::int64_t id) const {
  auto query = db_.Prepare(std::string(kSweepColumns) + " WHERE id = ?");
  query.Bind(1, id);
  if (!query.Step()) return std::nullopt;
  return SweepFromRow(query);
}

std::vector<QueuedRun> QueueStore::Runs(std::int64_t sweep_id) const {
  std::vector<QueuedRun> runs;
  auto query = db_.Prepare(
      "SELECT sweep_id, run_id, position, state, attempt, reused_from, wall_s, reason, spec FROM runs "
      "WHERE sweep_id = ? ORDER BY position");
  query.Bind(1, sweep_id);
  while (query.Step()) {
    QueuedRun run;
    run.sweep_id = query.Int64(0);
    run.run_id = query.Text(1);
    run.position = query.Int64(2);
    run.state = ParseRunState(query.Text(3));
    run.attempt = static_cast<int>(query.Int64(4));
    if (!query.IsNull(5)) run.reused_from = query.Int64(5);
    run.wall_s = query.OptionalDouble(6);
    run.reason = query.Text(7);
    run.spec = nlohmann::json::parse(query.Text(8));
    runs.push_back(std::move(run));
  }
  return runs;
}

void QueueStore::SetSweepState(std::int64_t id, QueuedSweepState state, const std::string& message) {
  SqliteTransaction transaction(db_);
  // started_at is set once, when the sweep first leaves the queued state; finished_at whenever it finishes.
  auto update = db_.Prepare(
      "UPDATE sweeps SET state = ?, message = ?, "
      "started_at = CASE WHEN started_at = '' AND ? THEN ? ELSE started_at END, "
      "finished_at = CASE WHEN ? THEN ? ELSE finished_at END WHERE id = ?");
  const std::string now = UtcNowIso8601();
  update.Bind(1, ToString(state))
      .Bind(2, std::string_view(message))
      .Bind(3, static_cast<std::int64_t>(state != QueuedSweepState::kQueued ? 1 : 0))
      .Bind(4, std::string_view(now))
      .Bind(5, static_cast<std::int64_t>(IsFinished(state) ? 1 : 0))
      .Bind(6, std::string_view(now))
      .Bind(7, id);
  update.Run();
  transaction.Commit();
}

void QueueStore::RequestCancel(std::int64_t id) {
  SqliteTransaction transaction(db_);
  auto update = db_.Prepare("UPDATE sweeps SET cancel_requested = 1 WHERE id = ?");
  update.Bind(1, id);
  update.Run();
  transaction.Commit();
}

void QueueStore::SetRunState(std::int64_t sweep_id, const std::string& run_id, QueuedRunState state,
                             bool attempt_started, std::optional<double> wall_s, const std::string& reason,
                             std::optional<std::int64_t> reused_from) {
  SqliteTransaction transaction(db_);
  auto update = db_.Prepare(
      "UPDATE runs SET state = ?, attempt = attempt + ?, wall_s = ?, reason = ?, reused_from = ? "
      "WHERE sweep_id = ? AND run_id = ?");
  update.Bind(1, ToString(state)).Bind(2, static_cast<std::int64_t>(attempt_started ? 1 : 0));
  if (wall_s) {
    update.Bind(3, *wall_s);
  } else {
    update.BindNull(3);
  }
  update.Bind(4, std::string_view(reason));
  if (reused_from) {
    update.Bind(5, *reused_from);
  } else {
    update.BindNull(5);
  }
  update.Bind(6, sweep_id).Bind(7, std::string_view(run_id));
  update.Run();
  transaction.Commit();
}

std::size_t QueueStore::RequeueRunning() {
  SqliteTransaction transaction(db_);
  auto count = db_.Prepare("SELECT COUNT(*) FROM runs WHERE state = ?");
  count.Bind(1, ToString(QueuedRunState::kRunning));
  count.Step();
  const auto requeued = static_cast<std::size_t>(count.Int64(0));
  auto requeue = db_.Prepare("UPDATE runs SET state = ? WHERE state = ?");
  requeue.Bind(1, ToString(QueuedRunState::kQueued)).Bind(2, ToString(QueuedRunState::kRunning));
  requeue.Run();
  transaction.Commit();
  return requeued;
}

std::vector<std::int64_t> QueueStore::SweepsWithOkRun(const std::string& run_id, std::int64_t except_sweep) const {
  std::vector<std::int64_t> sweeps;
  auto query = db_.Prepare(
      "SELECT sweep_id FROM runs WHERE run_id = ? AND state IN (?, ?) AND sweep_id <> ? ORDER BY sweep_id DESC");
  query.Bind(1, std::string_view(run_id))
      .Bind(2, ToString(QueuedRunState::kOk))
      .Bind(3, ToString(QueuedRunState::kReused))
      .Bind(4, except_sweep);
  while (query.Step()) sweeps.push_back(query.Int64(0));
  return sweeps;
}

}  // namespace slamsweep::orchestrator::service
