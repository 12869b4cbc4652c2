#include "orchestrator/store/store_schema.h"

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/matrix/run_id.h"

namespace slamsweep::orchestrator::inline store {
namespace {

using nlohmann::json;

// Versions 1-3 kept the whole run.json and result.json of every run beside the columns (about 50 KB a
// run). A store of version 1 or 2 gets the columns of version 3 first, then is converted to version 4.
constexpr const char* kMigrationV2 = R"sql(
ALTER TABLE runs ADD COLUMN parameters TEXT;
ALTER TABLE runs ADD COLUMN odometry_is_reference INTEGER;
ALTER TABLE runs ADD COLUMN seeding TEXT;
ALTER TABLE runs ADD COLUMN slamsweep_revision TEXT;
)sql";

constexpr const char* kMigrationV3 = R"sql(
ALTER TABLE runs ADD COLUMN flags TEXT;
)sql";

// Version 4: what a query needs, each thing once. A run's row holds its columns; what many runs share
// (run.json but its run_id, iteration and seed; the program's command, outputs and warnings; a metric's
// specification) is a document kept once; metric values are (run, name, value) rows of integers and a
// double. The run folder's run.json and result.json stay the complete record (result.json is the commit
// point of a run); the views `metrics` and `metric_specs` answer the queries of the older tables.
constexpr const char* kSchemaV4 = R"sql(
CREATE TABLE documents(
  id INTEGER PRIMARY KEY, digest INTEGER NOT NULL UNIQUE, json TEXT NOT NULL);
CREATE TABLE runs(
  id INTEGER PRIMARY KEY,
  run_id TEXT NOT NULL UNIQUE,
  sweep_id INTEGER, algorithm TEXT, adapter TEXT, parameters_json TEXT, sequence TEXT, noise TEXT,
  iteration INTEGER, seed,
  status TEXT NOT NULL CHECK(status IN ('ok', 'failed')), failure_kind TEXT, reason TEXT,
  exit_code INTEGER, signal INTEGER, wall_s REAL, cpu_s REAL, peak_rss_kb INTEGER,
  started_at TEXT, finished_at TEXT, run_dir TEXT,
  parameters TEXT, odometry_is_reference INTEGER, seeding TEXT, slamsweep_revision TEXT, flags TEXT,
  spec_shared INTEGER NOT NULL REFERENCES documents(id), spec_own TEXT NOT NULL,
  result_shared INTEGER NOT NULL REFERENCES documents(id), result_digest INTEGER NOT NULL);
CREATE INDEX runs_group ON runs(sequence, noise, algorithm, parameters);
CREATE INDEX runs_algorithm_sequence ON runs(algorithm, sequence);
CREATE TABLE metric_names(
  id INTEGER PRIMARY KEY, metric TEXT NOT NULL, statistic TEXT NOT NULL, unit TEXT NOT NULL,
  UNIQUE(metric, statistic, unit));
CREATE TABLE metric_values(
  run INTEGER NOT NULL REFERENCES runs(id), position INTEGER NOT NULL,
  name INTEGER NOT NULL REFERENCES metric_names(id), value REAL,
  PRIMARY KEY(run, position)) WITHOUT ROWID;
CREATE TABLE metric_spec_refs(
  run INTEGER NOT NULL REFERENCES runs(id), metric TEXT NOT NULL, spec INTEGER NOT NULL REFERENCES documents(id),
  PRIMARY KEY(run, metric)) WITHOUT ROWID;
CREATE VIEW metrics(run_id, metric, statistic, value, unit) AS
  SELECT runs.run_id, metric_names.metric, metric_names.statistic, metric_values.value,
         NULLIF(metric_names.unit, '')
  FROM metric_values JOIN runs ON runs.id = metric_values.run JOIN metric_names ON metric_names.id = metric_values.name;
CREATE VIEW metric_specs(run_id, metric, spec_json) AS
  SELECT runs.run_id, metric_spec_refs.metric, documents.json
  FROM metric_spec_refs JOIN runs ON runs.id = metric_spec_refs.run JOIN documents ON documents.id = metric_spec_refs.spec;
)sql";

json ParseV3(const SqliteDb& db, const std::string& run_id, const char* column, const std::string& text) {
  json parsed = json::parse(text, nullptr, false);
  if (parsed.is_discarded()) {
    throw evaluator::InputError(
        fmt::format("{}: run {}: column {} does not hold valid JSON; the database was "
                    "edited or is damaged: re-record the run from its runs/ folder",
                    db.file().string(), run_id, column));
  }
  return parsed;
}

// Converts the runs of a version 3 store (whole run.json/result.json texts) to version 4's tables.
void ConvertV3(SqliteDb& db, const std::function<void(const V3Run&)>& record_v3_run) {
  db.Execute(R"sql(
ALTER TABLE runs RENAME TO runs_v3;
DROP INDEX IF EXISTS runs_algorithm_sequence;
DROP INDEX IF EXISTS runs_sequence_algorithm;
DROP INDEX IF EXISTS runs_group;
DROP TABLE metrics;
DROP TABLE metric_specs;
)sql");
  db.Execute(kSchemaV4);
  {
    auto select =
        db.Prepare("SELECT run_id, sweep_id, spec_json, result_json, run_dir, flags FROM runs_v3 ORDER BY rowid");
    while (select.Step()) {
      V3Run run;
      const std::string run_id = select.Text(0);
      run.sweep_id = select.Int64(1);
      run.spec = ParseV3(db, run_id, "spec_json", select.Text(2));
      run.result = ParseV3(db, run_id, "result_json", select.Text(3));
      run.run_dir = select.IsNull(4) ? "" : select.Text(4);
      if (!select.IsNull(5)) run.flags = select.Text(5);
      record_v3_run(run);
    }
  }
  db.Execute("DROP TABLE runs_v3");
}

}  // namespace

void CreateOrMigrateSchema(SqliteDb& db, std::int64_t from_version,
                           const std::function<void(const V3Run&)>& record_v3_run) {
  if (from_version == 0) {
    db.Execute(
        "CREATE TABLE sweeps(id INTEGER PRIMARY KEY, name TEXT, config_path TEXT, config_sha TEXT, "
        "started_at TEXT, finished_at TEXT, status TEXT, host TEXT, slamsweep_version TEXT, "
        "run_count INTEGER, command_line TEXT)");
    db.Execute(kSchemaV4);
  } else {
    if (from_version < 2) db.Execute(kMigrationV2);
    if (from_version < 3) db.Execute(kMigrationV3);
    if (from_version < 4) ConvertV3(db, record_v3_run);
  }
  db.Execute(fmt::format("PRAGMA user_version = {}", kResultsSchemaVersion));
}

std::int64_t DocumentId(SqliteDb& db, const json& value) {
  const std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
  // SQLite integers are signed: the 64-bit digest is stored as its two's complement.
  const auto digest = static_cast<std::int64_t>(Fnv1a64(text));
  auto find = db.Prepare("SELECT id, json FROM documents WHERE digest = ?");
  find.Bind(1, digest);
  if (find.Step()) {
    if (find.Text(1) != text) {
      throw evaluator::InputError(
          fmt::format("{}: two different documents share the digest {:016x}; record the "
                      "sweep into a new output directory",
                      db.file().string(), static_cast<std::uint64_t>(digest)));
    }
    return find.Int64(0);
  }
  auto insert = db.Prepare("INSERT INTO documents(digest, json) VALUES(?, ?)");
  insert.Bind(1, digest).Bind(2, std::string_view(text));
  insert.Run();
  return db.LastInsertRowId();
}

}  // namespace slamsweep::orchestrator::inline store
