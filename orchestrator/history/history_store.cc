#include "orchestrator/history/history_store.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <set>
#include <vector>

#include "evaluator/core/input_error.h"
#include "orchestrator/history/series_odometry.h"
#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator::inline history {
namespace {

/// The comparable odometry modes of a night's series ("recorded", "reference").
std::set<std::string> ComparableModesOf(const Night& night) {
  std::set<std::string> modes;
  for (const SampleSeries& series : night.series) {
    if (IsComparableOdometryMode(series.odometry)) modes.insert(series.odometry);
  }
  return modes;
}

using evaluator::InputError;

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
    throw InputError(
        fmt::format("{}: samples.values_json: expected a JSON array of numbers; the history database "
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
    throw InputError(
        fmt::format("{}: no such history database; record a night first with `slamsweep history "
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
    throw InputError(
        fmt::format("{}: an SQLite database but not a slamsweep history database (a results.sqlite?); "
                    "--history expects its own file, e.g. /var/lib/slamsweep/history.sqlite",
                    db_.file().string()));
  }
  if (version > kHistorySchemaVersion) {
    throw InputError(
        fmt::format("{}: history schema version {} is newer than this slamsweep's ({}); use a newer "
                    "slamsweep",
                    db_.file().string(), version, kHistorySchemaVersion));
  }
  db_.Execute("PRAGMA journal_mode = WAL");
  if (version == kHistorySchemaVersion) return;
  SqliteTransaction transaction(db_);
  // Another process may have created or migrated the schema between the first read and the write lock.
  const std::int64_t locked_version = pragma("PRAGMA user_version");
  const std::int64_t locked_tables = pragma("SELECT count(*) FROM sqlite_master WHERE type = 'table'");
  if (locked_version != kHistorySchemaVersion) {
    CreateOrMigrateHistorySchema(db_, locked_tables == 0 ? 0 : locked_version);
  }
  transaction.Commit();
}

HistoryStore::RecordOutcome HistoryStore::Record(const Night& night) {
  SqliteTransaction transaction(db_);
  if (const auto existing = FindByKey(night.result_dir, night.sweep_id)) return {existing->id, false};
  if (const auto clash = FindByLabel(night.label)) {
    throw InputError(
        fmt::format("--label: night '{}' is already recorded for {} (sweep {}); give this sweep another "
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
      "INSERT INTO samples(night_id, algorithm, sequence, noise, odometry, metric, statistic, unit, values_json) "
      "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?)");
  for (const SampleSeries& s : night.series) {
    sample.Reset();
    sample.Bind(1, id)
        .Bind(2, s.algorithm)
        .Bind(3, s.sequence)
        .Bind(4, s.noise)
        .Bind(5, s.odometry)
        .Bind(6, s.metric)
        .Bind(7, s.statistic)
        .Bind(8, s.unit)
        .Bind(9, nlohmann::json(s.values).dump());
    sample.Run();
  }
  auto cell = db_.Prepare(
      "INSERT INTO cells(night_id, algorithm, sequence, noise, odometry, ok_runs, failed_runs) "
      "VALUES(?, ?, ?, ?, ?, ?, ?)");
  for (const CellCounts& c : night.cells) {
    cell.Reset();
    cell.Bind(1, id).Bind(2, c.algorithm).Bind(3, c.sequence).Bind(4, c.noise).Bind(5, c.odometry);
    cell.Bind(6, c.ok_runs).Bind(7, c.failed_runs);
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
      "SELECT algorithm, sequence, noise, odometry, metric, statistic, unit, values_json FROM samples "
      "WHERE night_id = ? ORDER BY algorithm, sequence, noise, odometry, metric, statistic");
  samples.Bind(1, night_id);
  while (samples.Step()) {
    night.series.push_back({{samples.Text(0), samples.Text(1), samples.Text(2), samples.Text(3), samples.Text(4),
                             samples.Text(5), NullableText(samples, 6)},
                            ParseValues(db_.file(), samples.Text(7))});
  }
  auto cells = db_.Prepare(
      "SELECT algorithm, sequence, noise, odometry, ok_runs, failed_runs FROM cells WHERE night_id = ? "
      "ORDER BY algorithm, sequence, noise, odometry");
  cells.Bind(1, night_id);
  while (cells.Step()) {
    night.cells.push_back({cells.Text(0), cells.Text(1), cells.Text(2), cells.Text(3), cells.Int64(4), cells.Int64(5)});
  }
  return night;
}

std::vector<HistoryPoint> HistoryStore::Series(const SeriesKey& key) const {
  auto select = db_.Prepare(
      "SELECT n.id, n.label, n.result_dir, n.sweep_id, n.sweep_name, n.started_at, n.recorded_at, n.report_index, "
      "s.values_json, COALESCE(c.failed_runs, 0) FROM samples s JOIN nights n ON n.id = s.night_id "
      "LEFT JOIN cells c ON c.night_id = s.night_id AND c.algorithm = s.algorithm AND c.sequence = s.sequence AND "
      "c.noise = s.noise AND c.odometry = s.odometry "
      "WHERE s.algorithm = ? AND s.sequence = ? AND s.noise = ? AND s.odometry = ? AND s.metric = ? AND "
      "s.statistic = ? ORDER BY n.id");
  select.Bind(1, key.algorithm).Bind(2, key.sequence).Bind(3, key.noise).Bind(4, key.odometry);
  select.Bind(5, key.metric).Bind(6, key.statistic);
  std::vector<HistoryPoint> points;
  while (select.Step()) {
    points.push_back({ReadEntry(select), ParseValues(db_.file(), select.Text(8)), select.Int64(9)});
  }
  return points;
}

std::vector<SeriesKey> HistoryStore::SeriesKeys() const {
  auto select = db_.Prepare(
      "SELECT algorithm, sequence, noise, odometry, metric, statistic, unit FROM samples WHERE rowid IN (SELECT "
      "max(rowid) FROM samples GROUP BY algorithm, sequence, noise, odometry, metric, statistic) "
      "ORDER BY algorithm, sequence, noise, odometry, metric, statistic");
  std::vector<SeriesKey> keys;
  while (select.Step()) {
    keys.push_back({select.Text(0), select.Text(1), select.Text(2), select.Text(3), select.Text(4), select.Text(5),
                    NullableText(select, 6)});
  }
  return keys;
}

std::optional<NightEntry> PreviousNight(const HistoryStore& store, const Night& current) {
  const auto recorded = store.FindByKey(current.result_dir, current.sweep_id);
  std::vector<NightEntry> earlier;
  for (const NightEntry& night : store.Nights()) {
    if (recorded && night.id >= recorded->id) break;
    earlier.push_back(night);
  }
  // A night of the other odometry mode has nothing to compare with: it is passed over.
  const std::set<std::string> modes = ComparableModesOf(current);
  for (auto night = earlier.rbegin(); night != earlier.rend(); ++night) {
    if (modes.empty()) return *night;
    const std::set<std::string> its = ComparableModesOf(store.Load(night->id));
    if (std::any_of(its.begin(), its.end(), [&](const std::string& mode) { return modes.contains(mode); }))
      return *night;
  }
  return std::nullopt;
}

}  // namespace slamsweep::orchestrator::inline history
