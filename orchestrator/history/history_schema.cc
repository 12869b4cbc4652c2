#include "orchestrator/history/history_schema.h"

#include <map>
#include <string>

#include <fmt/format.h>

#include "orchestrator/history/series_odometry.h"

namespace slamsweep::orchestrator {
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
  std::map<std::int64_t, std::map<NightCell, std::string>> modes_of_night;
  {
    auto nights = db.Prepare("SELECT id, result_dir, sweep_id FROM nights ORDER BY id");
    while (nights.Step()) {
      modes_of_night[nights.Int64(0)] = OdometryModesOfResultDir(nights.Text(1), nights.Int64(2));
    }
  }
  const auto mode_of = [&](std::int64_t night, const NightCell& cell) {
    const auto& modes = modes_of_night[night];
    const auto found = modes.find(cell);
    return found == modes.end() ? std::string(kOdometryUnknown) : found->second;
  };
  {
    auto select = db.Prepare(
        "SELECT night_id, algorithm, sequence, noise, metric, statistic, unit, values_json FROM samples_v1 "
        "ORDER BY rowid");
    auto insert = db.Prepare(
        "INSERT INTO samples(night_id, algorithm, sequence, noise, odometry, metric, statistic, unit, values_json) "
        "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?)");
    while (select.Step()) {
      const std::int64_t night = select.Int64(0);
      insert.Reset();
      insert.Bind(1, night).Bind(2, select.Text(1)).Bind(3, select.Text(2)).Bind(4, select.Text(3));
      insert.Bind(5, mode_of(night, {select.Text(1), select.Text(2), select.Text(3)}));
      insert.Bind(6, select.Text(4)).Bind(7, select.Text(5));
      if (select.IsNull(6)) {
        insert.BindNull(8);
      } else {
        insert.Bind(8, select.Text(6));
      }
      insert.Bind(9, select.Text(7));
      insert.Run();
    }
  }
  {
    auto select = db.Prepare(
        "SELECT night_id, algorithm, sequence, noise, ok_runs, failed_runs FROM cells_v1 ORDER BY rowid");
    auto insert = db.Prepare(
        "INSERT INTO cells(night_id, algorithm, sequence, noise, odometry, ok_runs, failed_runs) "
        "VALUES(?, ?, ?, ?, ?, ?, ?)");
    while (select.Step()) {
      const std::int64_t night = select.Int64(0);
      insert.Reset();
      insert.Bind(1, night).Bind(2, select.Text(1)).Bind(3, select.Text(2)).Bind(4, select.Text(3));
      insert.Bind(5, mode_of(night, {select.Text(1), select.Text(2), select.Text(3)}));
      insert.Bind(6, select.Int64(4)).Bind(7, select.Int64(5));
      insert.Run();
    }
  }
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

}  // namespace slamsweep::orchestrator
