#include "orchestrator/history/history_store.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "evaluator/core/input_error.h"
#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator {
namespace {

using evaluator::InputError;

// Tells a history file from a results.sqlite (both are slamsweep SQLite files with a user_version).
constexpr std::int64_t kHistoryApplicationId = 0x534C4853;  // "SLHS"

// Samples are kept as a JSON array per series: a night is read and written whole, never queried by value.
constexpr const char* kSchemaV1 = R"sql(
CREATE TABLE nights(
  id INTEGER PRIMARY KEY,
  label TEXT NOT NULL UNIQUE,
  result_dir TEXT NOT NULL, sweep_id INTEGER NOT NULL, sweep_name TEXT, started_at TEXT, recorded_at TEXT,
  report_index TEXT,
  UNIQUE(result_dir, sweep_id));
CREATE TABLE samples(
  night_id INTEGER NOT NULL REFERENCES nights(id),
  algorithm TEXT NOT NULL, sequence TEXT NOT NULL, noise TEXT NOT NULL, metric TEXT NOT NULL,
  statistic TEXT NOT NULL, unit TEXT, values_json TEXT NOT NULL,
  PRIMARY KEY(night_id, algorithm, sequence, noise, metric, statistic));
CREATE INDEX samples_series ON samples(algorithm, sequence, noise, metric, statistic);
CREATE TABLE cells(
  night_id INTEGER NOT NULL REFERENCES nights(id),
  algorithm TEXT NOT NULL, sequence TEXT NOT NULL, noise TEXT NOT NULL,
  ok_runs INTEGER NOT NULL, failed_runs INTEGER NOT NULL,
  PRIMARY KEY(night_id, algorithm, sequence, noise));
)sql";

constexpr const char* kNightColumns =
    "SELECT id, label, result_dir, sweep_id, sweep_name, started_at, recorded_at, report_index FROM nights";

std::string NullableText(const SqliteStatement& row, int column) { return row.IsNull(column) ? "" : row.Text(column); }

NightEntry ReadEntry(const SqliteStatement& row) {
  NightEntry entry;
  entry.id = row.Int64(0);
  entry.label = row.Text(1);
  entry.result_dir = row.Text(2);
  entry.sweep_id = row.Int64(3);
  entry.sweep_name = NullableText(row, 4);
  entry.started_at = NullableText(row, 5);
  entry.recorded_at = NullableText(row, 6);
  entry.report_index = NullableText(row, 7);
  return entry;
}

std::vector<double> ParseValues(const std::filesystem::path& file, const std::string& text) {
  const nlohmann::json parsed = nlohmann::json::parse(text, nullptr, false);
  std::vector<double> values;
  if (!parsed.is_array()) {
    throw InputError(fmt::format("{}: samples.values_json: expected a JSON array of numbers; the history database "
                                 "was edited or is damaged",
                                 file.string()));
  }
  for (const auto& v : parsed) {
    if (v.is_number()) values.push_back(v.get<double>());
  }
  return values;
}

}  // namespace

HistoryStore HistoryStore::Open(const std::filesystem::path& file) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  return OpenImpl(file, true);
}

HistoryStore HistoryStore::OpenExisting(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) {
    throw InputError(fmt::format("{}: no such history database; record a night first with `slamsweep history "
                                 "record RESULT_DIR --history {}`",
                                 file.string(), file.string()));
  }
  return OpenImpl(file, false);
}

HistoryStore HistoryStore::OpenImpl(const std::filesystem::path& file, bool create) {
  HistoryStore store(SqliteDb::Open(file, create));
  store.InitializeSchema();
  return store;
}

void HistoryStore::InitializeSchema() {
  const auto pragma = [this](const char* sql) {
    auto statement = db_.Prepare(sql);
    statement.Step();
    return statement.Int64(0);
  };
  const std::int64_t version = pragma("PRAGMA user_version");
  const std::int64_t application_id = pragma("PRAGMA application_id");
  const std::int64_t tables = pragma("SELECT count(*) FROM sqlite_master WHERE type = 'table'");
  if (tables > 0 && application_id != kHistoryApplicationId) {
    throw InputError(fmt::format("{}: an SQLite database but not a slamsweep history database (a results.sqlite?); "
                                 "--history expects its own file, e.g. /var/lib/slamsweep/history.sqlite",
                                 db_.file().string()));
  }
  if (version > kHistorySchemaVersion) {
    throw InputError(fmt::format("{}: history schema version {} is newer than this slamsweep's ({}); use a newer "
                                 "slamsweep",
                                 db_.file().string(), version, kHistorySchemaVersion));
  }
  db_.Execute("PRAGMA journal_mode = WAL");
  if (tables == 0) {
    SqliteTransaction transaction(db_);
    db_.Execute(kSchemaV1);
    db_.Execute(fmt::format("PRAGMA application_id = {}; PRAGMA user_version = {}", kHistoryApplicationId,
                            kHistorySchemaVersion));
    transaction.Commit();
  }
}

HistoryStore::RecordOutcome HistoryStore::Record(const Night& night) {
  SqliteTransaction transaction(db_);
  if (const auto existing = FindByKey(night.result_dir, night.sweep_id)) return {existing->id, false};
  if (const auto clash = FindByLabel(night.label)) {
    throw InputError(fmt::format("--label: night '{}' is already recorded for {} (sweep {}); give this sweep another "
                                 "label",
                                 night.label, clash->result_dir.string(), clash->sweep_id));
  }
  auto insert = db_.Prepare(
      "INSERT INTO nights(label, result_dir, sweep_id, sweep_name, started_at, recorded_at, report_index) "
      "VALUES(?, ?, ?, ?, ?, ?, ?)");
  insert.Bind(1, night.label)
      .Bind(2, night.result_dir.string())
      .Bind(3, night.sweep_id)
      .Bind(4, night.sweep_name)
      .Bind(5, night.started_at)
      .Bind(6, UtcNowIso8601())
      .Bind(7, night.report_index.string());
  insert.Run();
  const std::int64_t id = db_.LastInsertRowId();
  auto sample = db_.Prepare(
      "INSERT INTO samples(night_id, algorithm, sequence, noise, metric, statistic, unit, values_json) "
      "VALUES(?, ?, ?, ?, ?, ?, ?, ?)");
  for (const SampleSeries& s : night.series) {
    sample.Reset();
    sample.Bind(1, id)
        .Bind(2, s.algorithm)
        .Bind(3, s.sequence)
        .Bind(4, s.noise)
        .Bind(5, s.metric)
        .Bind(6, s.statistic)
        .Bind(7, s.unit)
        .Bind(8, nlohmann::json(s.values).dump());
    sample.Run();
  }
  auto cell = db_.Prepare(
      "INSERT INTO cells(night_id, algorithm, sequence, noise, ok_runs, failed_runs) VALUES(?, ?, ?, ?, ?, ?)");
  for (const CellCounts& c : night.cells) {
    cell.Reset();
    cell.Bind(1, id).Bind(2, c.algorithm).Bind(3, c.sequence).Bind(4, c.noise).Bind(5, c.ok_runs).Bind(6,
                                                                                                         c.failed_runs);
    cell.Run();
  }
  transaction.Commit();
  return {id, true};
}

std::vector<NightEntry> HistoryStore::QueryNights(const std::string& where, const std::string& text,
                                                  std::int64_t number) const {
  auto select = db_.Prepare(std::string(kNightColumns) + where + " ORDER BY id");
  if (where.find("?1") != std::string::npos) select.Bind(1, text);
  if (where.find("?2") != std::string::npos) select.Bind(2, number);
  std::vector<NightEntry> nights;
  while (select.Step()) nights.push_back(ReadEntry(select));
  return nights;
}

std::vector<NightEntry> HistoryStore::Nights() const { return QueryNights("", "", 0); }

std::optional<NightEntry> HistoryStore::FindByLabel(const std::string& label) const {
  auto found = QueryNights(" WHERE label = ?1", label, 0);
  if (found.empty()) return std::nullopt;
  return found.front();
}

std::optional<NightEntry> HistoryStore::FindByKey(const std::filesystem::path& result_dir,
                                                  std::int64_t sweep_id) const {
  auto found = QueryNights(" WHERE result_dir = ?1 AND sweep_id = ?2", result_dir.string(), sweep_id);
  if (found.empty()) return std::nullopt;
  return found.front();
}

Night HistoryStore::Load(std::int64_t night_id) const {
  auto select = db_.Prepare(std::string(kNightColumns) + " WHERE id = ?");
  select.Bind(1, night_id);
  if (!select.Step()) {
    throw InputError(fmt::format("{}: no night with id {}", db_.file().string(), night_id));
  }
  const NightEntry entry = ReadEntry(select);
  Night night;
  night.id = entry.id;
  night.label = entry.label;
  night.result_dir = entry.result_dir;
  night.sweep_id = entry.sweep_id;
  night.sweep_name = entry.sweep_name;
  night.started_at = entry.started_at;
  night.report_index = entry.report_index;
  auto samples = db_.Prepare(
      "SELECT algorithm, sequence, noise, metric, statistic, unit, values_json FROM samples WHERE night_id = ? "
      "ORDER BY algorithm, sequence, noise, metric, statistic");
  samples.Bind(1, night_id);
  while (samples.Step()) {
    night.series.push_back({samples.Text(0), samples.Text(1), samples.Text(2), samples.Text(3), samples.Text(4),
                            NullableText(samples, 5), ParseValues(db_.file(), samples.Text(6))});
  }
  auto cells = db_.Prepare(
      "SELECT algorithm, sequence, noise, ok_runs, failed_runs FROM cells WHERE night_id = ? "
      "ORDER BY algorithm, sequence, noise");
  cells.Bind(1, night_id);
  while (cells.Step()) {
    night.cells.push_back({cells.Text(0), cells.Text(1), cells.Text(2), cells.Int64(3), cells.Int64(4)});
  }
  return night;
}

std::vector<HistoryPoint> HistoryStore::Series(const std::string& algorithm, const std::string& sequence,
                                               const std::string& noise, const std::string& metric,
                                               const std::string& statistic) const {
  auto select = db_.Prepare(
      "SELECT n.id, n.label, n.result_dir, n.sweep_id, n.sweep_name, n.started_at, n.recorded_at, n.report_index, "
      "s.values_json, COALESCE(c.failed_runs, 0) FROM samples s JOIN nights n ON n.id = s.night_id "
      "LEFT JOIN cells c ON c.night_id = s.night_id AND c.algorithm = s.algorithm AND c.sequence = s.sequence AND "
      "c.noise = s.noise "
      "WHERE s.algorithm = ? AND s.sequence = ? AND s.noise = ? AND s.metric = ? AND s.statistic = ? ORDER BY n.id");
  select.Bind(1, algorithm).Bind(2, sequence).Bind(3, noise).Bind(4, metric).Bind(5, statistic);
  std::vector<HistoryPoint> points;
  while (select.Step()) {
    points.push_back({ReadEntry(select), ParseValues(db_.file(), select.Text(8)), select.Int64(9)});
  }
  return points;
}

std::vector<SeriesKey> HistoryStore::SeriesKeys() const {
  auto select = db_.Prepare(
      "SELECT algorithm, sequence, noise, metric, statistic, unit FROM samples WHERE rowid IN (SELECT max(rowid) "
      "FROM samples GROUP BY algorithm, sequence, noise, metric, statistic) "
      "ORDER BY algorithm, sequence, noise, metric, statistic");
  std::vector<SeriesKey> keys;
  while (select.Step()) {
    keys.push_back({select.Text(0), select.Text(1), select.Text(2), select.Text(3), select.Text(4),
                    NullableText(select, 5)});
  }
  return keys;
}

std::optional<NightEntry> PreviousNight(const HistoryStore& store, const Night& current) {
  const auto recorded = store.FindByKey(current.result_dir, current.sweep_id);
  std::optional<NightEntry> previous;
  for (const NightEntry& night : store.Nights()) {
    if (recorded && night.id >= recorded->id) break;
    previous = night;
  }
  return previous;
}

}  // namespace slamsweep::orchestrator
