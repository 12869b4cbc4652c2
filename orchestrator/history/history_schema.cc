#include "orchestrator/history/history_schema.h"

#include <string>

#include <fmt/format.h>

#include "orchestrator/history/series_odometry.h"

namespace slamsweep::orchestrator::inline history {
namespace {

constexpr const char* kNightsTable = R"sql(
CREATE TABLE nights(
  id INTEGER PRIMARY KEY,
  label TEXT NOT NULL UNIQUE,
  result_dir TEXT NOT NULL, sweep_id INTEGER NOT NULL, sweep_name TEXT, started_at TEXT, recorded_at TEXT,
  report_index TEXT,
  UNIQUE(result_dir, sweep_id));
)sql";

// Samples are kept as a JSON array per series: a night is read and written whole, never queried by value.
// A series is algorithm (with parameters) x sequence x noise x odometry mode x metric x statistic.
constexpr const char* kSeriesTablesV2 = R"sql(
CREATE TABLE samples(
  night_id INTEGER NOT NULL REFERENCES nights(id),
  algorithm TEXT NOT NULL, sequence TEXT NOT NULL, noise TEXT NOT NULL, odometry TEXT NOT NULL, metric TEXT NOT NULL,
  statistic TEXT NOT NULL, unit TEXT, values_json TEXT NOT NULL,
  PRIMARY KEY(night_id, algorithm, sequence, noise, odometry, metric, statistic));
CREATE INDEX samples_series ON samples(algorithm, sequence, noise, odometry, metric, statistic);
CREATE TABLE cells(
  night_id INTEGER NOT NULL REFERENCES nights(id),
  algorithm TEXT NOT NULL, sequence TEXT NOT NULL, noise TEXT NOT NULL, odometry TEXT NOT NULL,
  ok_runs INTEGER NOT NULL, failed_runs INTEGER NOT NULL,
  PRIMARY KEY(night_id, algorithm, sequence, noise, odometry));
)sql";

// Version 1 keyed series by algorithm x sequence x noise: its rows are copied with the mode of their cell.
void MigrateV1(SqliteDb& db) {
  db.Execute(R"sql(
ALTER TABLE samples RENAME TO samples_v1;
ALTER TABLE cells RENAME TO cells_v1;
DROP INDEX IF EXISTS samples_series;
)sql");
  db.Execute(kSeriesTablesV2);
  // The mode of every cell whose night's result directory still says it; any other row gets "unknown".
  db.Execute(
      "CREATE TEMP TABLE cell_modes(night_id INTEGER, algorithm TEXT, sequence TEXT, noise TEXT, "
      "odometry TEXT, PRIMARY KEY(night_id, algorithm, sequence, noise))");
  {
    auto nights = db.Prepare("SELECT id, result_dir, sweep_id FROM nights ORDER BY id");
    auto insert = db.Prepare("INSERT INTO cell_modes VALUES(?, ?, ?, ?, ?)");
    while (nights.Step()) {
      for (const auto& [cell, mode] : OdometryModesOfResultDir(nights.Text(1), nights.Int64(2))) {
        const auto& [algorithm, sequence, noise] = cell;
        insert.Reset();
        insert.Bind(1, nights.Int64(0)).Bind(2, algorithm).Bind(3, sequence).Bind(4, noise).Bind(5, mode);
        insert.Run();
      }
    }
  }
  const std::string mode_of_row = fmt::format(
      "COALESCE((SELECT m.odometry FROM cell_modes m WHERE m.night_id = v.night_id AND m.algorithm = v.algorithm "
      "AND m.sequence = v.sequence AND m.noise = v.noise), '{}')",
      kOdometryUnknown);
  db.Execute(fmt::format(
      "INSERT INTO samples(night_id, algorithm, sequence, noise, odometry, metric, statistic, unit, values_json) "
      "SELECT night_id, algorithm, sequence, noise, {}, metric, statistic, unit, values_json FROM samples_v1 v "
      "ORDER BY rowid",
      mode_of_row));
  db.Execute(fmt::format(
      "INSERT INTO cells(night_id, algorithm, sequence, noise, odometry, ok_runs, failed_runs) "
      "SELECT night_id, algorithm, sequence, noise, {}, ok_runs, failed_runs FROM cells_v1 v ORDER BY rowid",
      mode_of_row));
  db.Execute("DROP TABLE cell_modes;");
  db.Execute("DROP TABLE samples_v1; DROP TABLE cells_v1;");
}

}  // namespace

void CreateOrMigrateHistorySchema(SqliteDb& db, std::int64_t from_version) {
  if (from_version == 0) {
    db.Execute(kNightsTable);
    db.Execute(kSeriesTablesV2);
    db.Execute(fmt::format("PRAGMA application_id = {}", kHistoryApplicationId));
  } else if (from_version < 2) {
    MigrateV1(db);
  }
  db.Execute(fmt::format("PRAGMA user_version = {}", kHistorySchemaVersion));
}

}  // namespace slamsweep::orchestrator::inline history
