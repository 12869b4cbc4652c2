#include "orchestrator/store/results_store.h"

#include <algorithm>
#include <ctime>
#include <unordered_map>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/matrix/run_spec.h"

namespace slamsweep::orchestrator {
namespace {

using evaluator::InputError;
using nlohmann::json;

// Version 1 of the schema. Whole run.json / result.json are kept beside the columns so that a later
// report can read fields the columns do not have, and the store can be re-exported without the folders.
constexpr const char* kSchemaV1 = R"sql(
CREATE TABLE sweeps(
  id INTEGER PRIMARY KEY,
  name TEXT, config_path TEXT, config_sha TEXT, started_at TEXT, finished_at TEXT, status TEXT,
  host TEXT, slamsweep_version TEXT, run_count INTEGER, command_line TEXT);
CREATE TABLE runs(
  run_id TEXT PRIMARY KEY,
  sweep_id INTEGER, algorithm TEXT, adapter TEXT, parameters_json TEXT, sequence TEXT, noise TEXT,
  iteration INTEGER, seed, spec_json TEXT NOT NULL,
  status TEXT NOT NULL CHECK(status IN ('ok', 'failed')), failure_kind TEXT, reason TEXT,
  exit_code INTEGER, signal INTEGER, wall_s REAL, cpu_s REAL, peak_rss_kb INTEGER,
  started_at TEXT, finished_at TEXT, run_dir TEXT, result_json TEXT NOT NULL);
CREATE INDEX runs_algorithm_sequence ON runs(algorithm, sequence);
CREATE INDEX runs_sequence_algorithm ON runs(sequence, algorithm);
CREATE TABLE metrics(
  run_id TEXT NOT NULL, metric TEXT NOT NULL, statistic TEXT NOT NULL, value REAL, unit TEXT,
  PRIMARY KEY(run_id, metric, statistic));
CREATE TABLE metric_specs(
  run_id TEXT NOT NULL, metric TEXT NOT NULL, spec_json TEXT,
  PRIMARY KEY(run_id, metric));
)sql";

// Version 2: what makes rows comparable and results trustworthy, as columns a query can group by:
// the parameters as "k=v;..." text (the comparison group), whether the program's odometry was the
// reference, how the run is seeded, and the slamsweep revision that computed it.
constexpr const char* kMigrationV2 = R"sql(
ALTER TABLE runs ADD COLUMN parameters TEXT;
ALTER TABLE runs ADD COLUMN odometry_is_reference INTEGER;
ALTER TABLE runs ADD COLUMN seeding TEXT;
ALTER TABLE runs ADD COLUMN slamsweep_revision TEXT;
CREATE INDEX runs_group ON runs(sequence, noise, algorithm, parameters);
)sql";

// Version 3: the run's marks (RunFlags: odometry = reference, stale, unisolated) as "a;b" text.
constexpr const char* kMigrationV3 = R"sql(
ALTER TABLE runs ADD COLUMN flags TEXT;
)sql";

const json* Find(const json& object, const char* key) {
  if (!object.is_object()) return nullptr;
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

// A field for a column: whatever JSON value is there (null when missing); BindJson stores any type.
const json& FieldOrNull(const json& object, const char* key) {
  static const json kNull;
  const json* found = Find(object, key);
  return found != nullptr ? *found : kNull;
}

const json& Nested(const json& object, const char* outer, const char* inner) {
  return FieldOrNull(FieldOrNull(object, outer), inner);
}

// Invalid UTF-8 (a reason quoting a program's garbled output) is replaced rather than refusing the whole run.
std::string Dump(const json& value) { return value.dump(-1, ' ', false, json::error_handler_t::replace); }

std::string NullableText(const SqliteStatement& row, int column) { return row.IsNull(column) ? "" : row.Text(column); }

json ParseStored(const std::filesystem::path& file, const std::string& run_id, const char* column,
                 const std::string& text) {
  json parsed = json::parse(text, nullptr, false);
  if (parsed.is_discarded()) {
    throw InputError(fmt::format("{}: run {}: column {} does not hold valid JSON; the database was edited or is "
                                 "damaged: re-record the run from its runs/ folder",
                                 file.string(), run_id, column));
  }
  return parsed;
}

struct RunColumns {
  std::string run_id;
  std::string status;
};

// Checks what the store cannot do without; other fields are stored as they are (null when absent).
RunColumns ValidateRun(const json& run_spec, const json& result) {
  if (!run_spec.is_object()) throw InputError("run.json: expected a JSON object");
  if (!result.is_object()) throw InputError("result.json: expected a JSON object");
  const json* run_id = Find(run_spec, "run_id");
  if (run_id == nullptr || !run_id->is_string() || run_id->get_ref<const std::string&>().empty()) {
    throw InputError("run.json: run_id: expected a non-empty string");
  }
  RunColumns columns{run_id->get<std::string>(), {}};
  const std::string where = fmt::format("result.json of run {}", columns.run_id);
  if (const json* result_id = Find(result, "run_id"); result_id != nullptr && *result_id != *run_id) {
    throw InputError(fmt::format("{}: run_id: expected \"{}\" (the run.json's), found {}", where, columns.run_id,
                                 Dump(*result_id)));
  }
  const json* status = Find(result, "status");
  if (status == nullptr || !status->is_string() || (*status != "ok" && *status != "failed")) {
    throw InputError(fmt::format("{}: status: expected \"ok\" or \"failed\", found {}", where,
                                 status == nullptr ? "nothing" : Dump(*status)));
  }
  columns.status = status->get<std::string>();
  if (const json* metrics = Find(result, "metrics"); metrics != nullptr && !metrics->is_null()) {
    if (!metrics->is_array()) throw InputError(fmt::format("{}: metrics: expected an array", where));
    for (std::size_t i = 0; i < metrics->size(); ++i) {
      const json& m = (*metrics)[i];
      for (const char* key : {"metric", "statistic"}) {
        const json* field = Find(m, key);
        if (field == nullptr || !field->is_string() || field->get_ref<const std::string&>().empty()) {
          throw InputError(fmt::format("{}: metrics[{}].{}: expected a non-empty string", where, i, key));
        }
      }
      const json& value = FieldOrNull(m, "value");
      if (!value.is_null() && !value.is_number()) {
        throw InputError(fmt::format("{}: metrics[{}].value: expected a number or null", where, i));
      }
      const json& unit = FieldOrNull(m, "unit");
      if (!unit.is_null() && !unit.is_string()) {
        throw InputError(fmt::format("{}: metrics[{}].unit: expected a string", where, i));
      }
    }
  }
  if (const json* details = Find(result, "metric_details");
      details != nullptr && !details->is_null() && !details->is_object()) {
    throw InputError(fmt::format("{}: metric_details: expected an object", where));
  }
  return columns;
}

// What the worker measured on the data when it got that far, else what the plan expected.
json OdometryIsReferenceOf(const json& run_spec, const json& result) {
  const json& measured = FieldOrNull(result, "odometry_is_reference");
  return measured.is_boolean() ? measured : FieldOrNull(run_spec, "odometry_is_reference");
}

// Median as evo and numpy define it: the mean of the middle two for an even count.
double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

constexpr const char* kRunColumns =
    "run_id, sweep_id, spec_json, result_json, status, run_dir, algorithm, sequence, noise, iteration, wall_s, "
    "finished_at, parameters, odometry_is_reference, seeding, flags";

}  // namespace

std::string TypicalWallKey(const std::string& algorithm, const std::string& sequence) {
  return algorithm + "\t" + sequence;
}

std::string UtcNowIso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

ResultsStore ResultsStore::Open(const std::filesystem::path& file) { return OpenImpl(file, true); }

ResultsStore ResultsStore::OpenExisting(const std::filesystem::path& file) { return OpenImpl(file, false); }

ResultsStore ResultsStore::OpenImpl(const std::filesystem::path& file, bool create) {
  ResultsStore store(SqliteDb::Open(file, create));
  store.InitializeSchema();
  return store;
}

void ResultsStore::InitializeSchema() {
  const auto read_version = [this] {
    auto version = db_.Prepare("PRAGMA user_version");
    version.Step();
    return version.Int64(0);
  };
  const auto count_tables = [this] {
    auto tables = db_.Prepare("SELECT count(*) FROM sqlite_master WHERE type = 'table'");
    tables.Step();
    return tables.Int64(0);
  };
  // The first read is where SQLite notices a file that is not a database. Version and tables are read
  // in one snapshot: another process creating the schema between the two reads would otherwise make
  // a new store look like a foreign database (tables, version 0).
  std::int64_t version = 0;
  std::int64_t tables = 0;
  {
    db_.Execute("BEGIN");
    try {
      version = read_version();
      tables = count_tables();
    } catch (...) {
      db_.Execute("ROLLBACK");
      throw;
    }
    db_.Execute("COMMIT");
  }
  if (version > kResultsSchemaVersion) {
    throw InputError(fmt::format("{}: results database schema version {} is newer than this slamsweep's ({}); "
                                 "use a newer slamsweep or another output directory",
                                 db_.file().string(), version, kResultsSchemaVersion));
  }
  if (version == 0 && tables > 0) {
    throw InputError(fmt::format("{}: an SQLite database but not a slamsweep results database (it has tables and "
                                 "no schema version); use another output directory",
                                 db_.file().string()));
  }
  // WAL lets readers (status, report) work while a sweep writes; it is a property of the file, kept once set.
  db_.Execute("PRAGMA journal_mode = WAL");
  db_.Execute("PRAGMA synchronous = NORMAL");
  if (version == kResultsSchemaVersion) return;
  SqliteTransaction transaction(db_);
  // Another process may have created or migrated the schema between the first read and the write lock.
  const std::int64_t locked_version = read_version();
  if (locked_version == 0) db_.Execute(kSchemaV1);
  if (locked_version < 2) db_.Execute(kMigrationV2);
  if (locked_version < 3) db_.Execute(kMigrationV3);
  db_.Execute(fmt::format("PRAGMA user_version = {}", kResultsSchemaVersion));
  transaction.Commit();
}

std::int64_t ResultsStore::BeginSweep(const SweepInfo& info) {
  SqliteTransaction transaction(db_);
  auto insert = db_.Prepare(
      "INSERT INTO sweeps(name, config_path, config_sha, started_at, status, host, slamsweep_version, run_count, "
      "command_line) VALUES(?, ?, ?, ?, 'running', ?, ?, 0, ?)");
  insert.Bind(1, info.name).Bind(2, info.config_path).Bind(3, info.config_sha);
  insert.Bind(4, info.started_at.empty() ? UtcNowIso8601() : info.started_at);
  insert.Bind(5, info.host).Bind(6, info.slamsweep_version).Bind(7, info.command_line);
  insert.Run();
  const std::int64_t id = db_.LastInsertRowId();
  transaction.Commit();
  return id;
}

void ResultsStore::FinishSweep(std::int64_t sweep_id, const std::string& status, std::int64_t run_count) {
  SqliteTransaction transaction(db_);
  auto update = db_.Prepare("UPDATE sweeps SET finished_at = ?, status = ?, run_count = ? WHERE id = ?");
  update.Bind(1, UtcNowIso8601()).Bind(2, status).Bind(3, run_count).Bind(4, sweep_id);
  update.Run();
  transaction.Commit();
}

std::vector<StoredSweep> ResultsStore::Sweeps() const {
  auto select = db_.Prepare(
      "SELECT id, name, config_path, config_sha, started_at, finished_at, status, host, slamsweep_version, "
      "run_count, command_line FROM sweeps ORDER BY id");
  std::vector<StoredSweep> sweeps;
  while (select.Step()) {
    StoredSweep s;
    s.id = select.Int64(0);
    s.info.name = NullableText(select, 1);
    s.info.config_path = NullableText(select, 2);
    s.info.config_sha = NullableText(select, 3);
    s.info.started_at = NullableText(select, 4);
    s.finished_at = NullableText(select, 5);
    s.status = NullableText(select, 6);
    s.info.host = NullableText(select, 7);
    s.info.slamsweep_version = NullableText(select, 8);
    s.run_count = select.Int64(9);
    s.info.command_line = NullableText(select, 10);
    sweeps.push_back(std::move(s));
  }
  return sweeps;
}

std::int64_t ResultsStore::ImportSweep(const StoredSweep& sweep) {
  SqliteTransaction transaction(db_);
  auto find = db_.Prepare(
      "SELECT id FROM sweeps WHERE name IS ? AND config_sha IS ? AND started_at IS ? AND host IS ? LIMIT 1");
  find.Bind(1, sweep.info.name).Bind(2, sweep.info.config_sha).Bind(3, sweep.info.started_at);
  find.Bind(4, sweep.info.host);
  if (find.Step()) {
    const std::int64_t id = find.Int64(0);
    transaction.Commit();
    return id;
  }
  auto insert = db_.Prepare(
      "INSERT INTO sweeps(name, config_path, config_sha, started_at, finished_at, status, host, slamsweep_version, "
      "run_count, command_line) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  insert.Bind(1, sweep.info.name).Bind(2, sweep.info.config_path).Bind(3, sweep.info.config_sha);
  insert.Bind(4, sweep.info.started_at).Bind(5, sweep.finished_at).Bind(6, sweep.status);
  insert.Bind(7, sweep.info.host).Bind(8, sweep.info.slamsweep_version).Bind(9, sweep.run_count);
  insert.Bind(10, sweep.info.command_line);
  insert.Run();
  const std::int64_t id = db_.LastInsertRowId();
  transaction.Commit();
  return id;
}

void ResultsStore::RecordRun(std::int64_t sweep_id, const json& run_spec, const json& result,
                             const std::string& run_dir_relative) {
  const RunColumns columns = ValidateRun(run_spec, result);
  const RunFlags flags = RunFlagsOf(run_spec, result);
  SqliteTransaction transaction(db_);
  {
    auto insert = db_.Prepare(
        "INSERT OR REPLACE INTO runs(run_id, sweep_id, algorithm, adapter, parameters_json, sequence, noise, "
        "iteration, seed, spec_json, status, failure_kind, reason, exit_code, signal, wall_s, cpu_s, peak_rss_kb, "
        "started_at, finished_at, run_dir, result_json, parameters, odometry_is_reference, seeding, "
        "slamsweep_revision, flags) "
        "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    const json& parameters = Nested(run_spec, "algorithm", "parameters");
    insert.Bind(1, columns.run_id).Bind(2, sweep_id);
    insert.BindJson(3, Nested(run_spec, "algorithm", "name")).BindJson(4, Nested(run_spec, "algorithm", "adapter"));
    if (parameters.is_null()) {
      insert.BindNull(5);
    } else {
      insert.Bind(5, std::string_view(Dump(parameters)));
    }
    insert.BindJson(6, Nested(run_spec, "sequence", "name")).BindJson(7, Nested(run_spec, "noise", "name"));
    insert.BindJson(8, FieldOrNull(run_spec, "iteration")).BindJson(9, FieldOrNull(run_spec, "seed"));
    insert.Bind(10, std::string_view(Dump(run_spec)));
    insert.Bind(11, columns.status);
    int index = 12;
    for (const char* key : {"failure_kind", "reason", "exit_code", "signal", "wall_s", "cpu_s", "peak_rss_kb",
                            "started_at", "finished_at"}) {
      insert.BindJson(index++, FieldOrNull(result, key));
    }
    insert.Bind(21, run_dir_relative).Bind(22, std::string_view(Dump(result)));
    insert.BindJson(23, Nested(run_spec, "group", "parameters"));
    insert.BindJson(24, OdometryIsReferenceOf(run_spec, result));
    insert.BindJson(25, FieldOrNull(run_spec, "seeding"));
    insert.BindJson(26, Nested(run_spec, "build", "slamsweep_revision"));
    insert.Bind(27, RunFlagsText(flags));
    insert.Run();
  }
  if (mid_transaction_hook_) mid_transaction_hook_();
  for (const char* table : {"metrics", "metric_specs"}) {
    auto remove = db_.Prepare(fmt::format("DELETE FROM {} WHERE run_id = ?", table));
    remove.Bind(1, columns.run_id);
    remove.Run();
  }
  if (const json* metrics = Find(result, "metrics"); metrics != nullptr && metrics->is_array()) {
    // A metric listed twice keeps its last value, as a JSON object with a repeated key would.
    auto insert = db_.Prepare("INSERT OR REPLACE INTO metrics(run_id, metric, statistic, value, unit) "
                              "VALUES(?, ?, ?, ?, ?)");
    for (const json& m : *metrics) {
      insert.Reset();
      insert.Bind(1, columns.run_id).BindJson(2, m.at("metric")).BindJson(3, m.at("statistic"));
      insert.BindJson(4, FieldOrNull(m, "value")).BindJson(5, FieldOrNull(m, "unit"));
      insert.Run();
    }
  }
  if (const json* details = Find(result, "metric_details"); details != nullptr && details->is_object()) {
    auto insert = db_.Prepare("INSERT INTO metric_specs(run_id, metric, spec_json) VALUES(?, ?, ?)");
    for (const auto& [metric, spec] : details->items()) {
      insert.Reset();
      insert.Bind(1, columns.run_id).Bind(2, metric).Bind(3, std::string_view(Dump(spec)));
      insert.Run();
    }
  }
  transaction.Commit();
}

std::optional<std::string> ResultsStore::RunStatus(const std::string& run_id) const {
  auto select = db_.Prepare("SELECT status FROM runs WHERE run_id = ?");
  select.Bind(1, run_id);
  if (!select.Step()) return std::nullopt;
  return select.Text(0);
}

std::optional<StoredRun> ResultsStore::FindRun(const std::string& run_id) const {
  std::vector<StoredRun> runs = QueryRuns("WHERE run_id = ?1", run_id);
  if (runs.empty()) return std::nullopt;
  return std::move(runs.front());
}

std::vector<StoredRun> ResultsStore::Runs() const { return QueryRuns("", ""); }

bool ResultsStore::AddRunFlags(const std::string& run_id, const RunFlags& added) {
  SqliteTransaction transaction(db_);
  auto select = db_.Prepare("SELECT spec_json, result_json, flags FROM runs WHERE run_id = ?");
  select.Bind(1, run_id);
  if (!select.Step()) return false;
  const json spec = ParseStored(db_.file(), run_id, "spec_json", select.Text(0));
  json result = ParseStored(db_.file(), run_id, "result_json", select.Text(1));
  RunFlags flags = select.IsNull(2) ? RunFlagsOf(spec, result)
                                    : RunFlagsFromText(select.Text(2), db_.file().string() + ": runs.flags");
  flags |= added;
  result["flags"] = ToJson(flags);
  auto update = db_.Prepare("UPDATE runs SET flags = ?, result_json = ? WHERE run_id = ?");
  update.Bind(1, RunFlagsText(flags)).Bind(2, std::string_view(Dump(result))).Bind(3, run_id);
  update.Run();
  transaction.Commit();
  return true;
}

std::vector<StoredRun> ResultsStore::QueryRuns(const std::string& where, const std::string& run_id) const {
  std::vector<StoredRun> runs;
  std::unordered_map<std::string, std::size_t> index_of;
  // Both reads see one snapshot, so a concurrent RecordRun cannot pair a run with another version's metrics.
  SqliteStatement begin = db_.Prepare("BEGIN");
  begin.Run();
  struct EndRead {
    const SqliteDb& db;
    ~EndRead() {
      try {
        db.Prepare("COMMIT").Run();
      } catch (const std::exception&) {
        // A read-only transaction has nothing to lose; ending it can only fail if it already ended.
      }
    }
  } end_read{db_};
  {
    auto select = db_.Prepare(fmt::format(
        "SELECT {} FROM runs {} ORDER BY sequence, algorithm, noise, iteration, run_id", kRunColumns, where));
    if (!where.empty()) select.Bind(1, run_id);
    while (select.Step()) {
      StoredRun run;
      run.run_id = select.Text(0);
      run.sweep_id = select.Int64(1);
      run.spec = ParseStored(db_.file(), run.run_id, "spec_json", select.Text(2));
      run.result = ParseStored(db_.file(), run.run_id, "result_json", select.Text(3));
      run.status = select.Text(4);
      run.run_dir = NullableText(select, 5);
      run.algorithm = NullableText(select, 6);
      run.sequence = NullableText(select, 7);
      run.noise = NullableText(select, 8);
      run.iteration = select.Int64(9);
      run.wall_s = select.OptionalDouble(10);
      run.finished_at = NullableText(select, 11);
      // Runs recorded before the column existed: the text from their parameters.
      run.parameters = select.IsNull(12) ? ParametersText(Nested(run.spec, "algorithm", "parameters"))
                                         : select.Text(12);
      run.odometry_is_reference = !select.IsNull(13) && select.Int64(13) != 0;
      run.seeding = NullableText(select, 14);
      // Runs recorded before the column existed: the flags their files imply.
      run.flags = select.IsNull(15) ? RunFlagsOf(run.spec, run.result)
                                    : RunFlagsFromText(select.Text(15), db_.file().string() + ": runs.flags");
      index_of.emplace(run.run_id, runs.size());
      runs.push_back(std::move(run));
    }
  }
  auto metrics = db_.Prepare(fmt::format(
      "SELECT run_id, metric, statistic, value, unit FROM metrics {} ORDER BY rowid", where));
  if (!where.empty()) metrics.Bind(1, run_id);
  while (metrics.Step()) {
    const auto it = index_of.find(metrics.Text(0));
    if (it == index_of.end()) continue;
    runs[it->second].metrics.push_back(
        StoredMetric{metrics.Text(1), metrics.Text(2), metrics.OptionalDouble(3), NullableText(metrics, 4)});
  }
  return runs;
}

std::map<std::string, double> ResultsStore::TypicalWallSeconds() const {
  auto select = db_.Prepare(
      "SELECT algorithm, sequence, wall_s FROM runs WHERE status = 'ok' AND wall_s IS NOT NULL");
  std::map<std::string, std::vector<double>> walls;
  while (select.Step()) {
    walls[TypicalWallKey(NullableText(select, 0), NullableText(select, 1))].push_back(select.Double(2));
  }
  std::map<std::string, double> typical;
  for (auto& [key, values] : walls) typical.emplace(key, Median(std::move(values)));
  return typical;
}

}  // namespace slamsweep::orchestrator
