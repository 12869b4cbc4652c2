#include "orchestrator/store/results_store.h"

#include <algorithm>
#include <unordered_map>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/matrix/run_id.h"
#include "orchestrator/run/run_json.h"
#include "orchestrator/store/store_schema.h"
#include "orchestrator/store/json_lookup.h"

namespace slamsweep::orchestrator {
namespace {

using evaluator::InputError;
using nlohmann::json;

// Invalid UTF-8 (a reason quoting a program's garbled output) is replaced rather than refusing the whole run.
std::string Dump(const json& value) { return value.dump(-1, ' ', false, json::error_handler_t::replace); }

std::string NullableText(const SqliteStatement& row, int column) { return row.IsNull(column) ? "" : row.Text(column); }

struct RunColumns {
  std::string run_id;
  RunStatus status = RunStatus::kFailed;
};

// A runs.status as RecordRun wrote it; anything else is a damaged database.
RunStatus StoredRunStatus(const std::filesystem::path& file, const std::string& run_id, const std::string& text) {
  const std::optional<RunStatus> status = RecordedRunStatus(text);
  if (!status) throw InputError(fmt::format("{}: runs.status of run {}: found \"{}\"", file.string(), run_id, text));
  return *status;
}

// The record's fields from the result.json the store keeps (its columns and shared members); a value of another
// type than result.json writes is left empty.
void FillResultFields(RunRecord& run) {
  const json& result = run.result;
  const auto text = [&](const char* key) {
    const auto found = result.find(key);
    return found != result.end() && found->is_string() ? found->get<std::string>() : std::string();
  };
  const auto number = [&](const char* key) -> std::optional<double> {
    const auto found = result.find(key);
    return found != result.end() && found->is_number() ? std::optional<double>(found->get<double>()) : std::nullopt;
  };
  const auto integer = [&](const char* key) -> std::optional<int> {
    const auto found = result.find(key);
    return found != result.end() && found->is_number_integer() ? std::optional<int>(found->get<int>()) : std::nullopt;
  };
  const auto strings = [&](const char* key) {
    std::vector<std::string> out;
    const auto found = result.find(key);
    if (found == result.end() || !found->is_array()) return out;
    for (const json& item : *found) {
      if (item.is_string()) out.push_back(item.get<std::string>());
    }
    return out;
  };
  run.failure_kind = text("failure_kind");
  run.reason = text("reason");
  run.exit_code = integer("exit_code");
  run.signal = integer("signal");
  run.cpu_s = number("cpu_s");
  run.peak_rss_kb = number("peak_rss_kb");
  run.started_at = text("started_at");
  run.command = strings("command");
  run.warnings = strings("warnings");
}

// Checks what the store cannot do without; other fields are stored as they are (null when absent).
RunColumns ValidateRun(const json& run_spec, const json& result) {
  if (!run_spec.is_object()) throw InputError("run.json: expected a JSON object");
  if (!result.is_object()) throw InputError("result.json: expected a JSON object");
  const json* run_id = FindField(run_spec, "run_id");
  if (run_id == nullptr || !run_id->is_string() || run_id->get_ref<const std::string&>().empty()) {
    throw InputError("run.json: run_id: expected a non-empty string");
  }
  RunColumns columns{run_id->get<std::string>(), {}};
  const std::string where = fmt::format("result.json of run {}", columns.run_id);
  if (const json* result_id = FindField(result, "run_id"); result_id != nullptr && *result_id != *run_id) {
    throw InputError(
        fmt::format("{}: run_id: expected \"{}\" (the run.json's), found {}", where, columns.run_id, Dump(*result_id)));
  }
  const json* status = FindField(result, "status");
  const std::optional<RunStatus> recorded = status != nullptr && status->is_string()
                                                ? RecordedRunStatus(status->get_ref<const std::string&>())
                                                : std::nullopt;
  if (!recorded) {
    throw InputError(fmt::format("{}: status: expected \"{}\" or \"{}\", found {}", where,
                                 RunStatusName(RunStatus::kOk), RunStatusName(RunStatus::kFailed),
                                 status == nullptr ? "nothing" : Dump(*status)));
  }
  columns.status = *recorded;
  if (const json* metrics = FindField(result, "metrics"); metrics != nullptr && !metrics->is_null()) {
    if (!metrics->is_array()) throw InputError(fmt::format("{}: metrics: expected an array", where));
    for (std::size_t i = 0; i < metrics->size(); ++i) {
      const json& m = (*metrics)[i];
      for (const char* key : {"metric", "statistic"}) {
        const json* field = FindField(m, key);
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
  if (const json* details = FindField(result, "metric_details");
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

// run.json members that differ from run to run of a group; the rest of run.json is shared (a document).
constexpr const char* kSpecOwnMembers[] = {"run_id", "iteration", "seed"};
// result.json members kept as columns (read back as they are; absent ones come back as null).
constexpr const char* kResultColumns[] = {"failure_kind", "reason",      "exit_code",  "signal",     "wall_s",
                                          "cpu_s",        "peak_rss_kb", "started_at", "finished_at"};
// result.json members a query needs beyond its columns, kept as one shared document per distinct value.
constexpr const char* kResultSharedMembers[] = {"command", "outputs", "warnings", "odometry_is_reference"};
// Where each of kResultColumns is in kRunColumns.
constexpr int kResultColumnIndex[] = {19, 20, 21, 22, 9, 23, 24, 25, 10};

constexpr const char* kRunColumns =
    "runs.id, run_id, sweep_id, status, run_dir, algorithm, sequence, noise, iteration, wall_s, finished_at, "
    "parameters, odometry_is_reference, seeding, flags, spec_own, spec_doc.json, result_doc.json, result_digest, "
    "failure_kind, reason, exit_code, signal, cpu_s, peak_rss_kb, started_at";

// What a query needs of a metric's details: how it was measured (its "specification" or "parameters"),
// not the numbers (those are the run's metric values; the whole details stay in result.json).
json MetricSpecification(const json& details) {
  json kept = json::object();
  if (!details.is_object()) return kept;
  for (const char* key : {"specification", "parameters"}) {
    if (const auto it = details.find(key); it != details.end()) kept[key] = *it;
  }
  return kept;
}

// The identity of a result for merge: its whole text but the flags (compared on their own, since the
// store adds flags to a recorded run without its file).
std::int64_t ResultDigest(const json& result) {
  json without_flags = result;
  without_flags.erase("flags");
  return static_cast<std::int64_t>(Fnv1a64(Dump(without_flags)));
}

// The metrics in the order the worker listed them; a metric listed twice keeps its last value and place,
// as a JSON object with a repeated key would.
std::vector<const json*> DistinctMetrics(const json& metrics) {
  std::map<std::pair<std::string, std::string>, std::size_t> last;
  for (std::size_t i = 0; i < metrics.size(); ++i) {
    last[{metrics[i].at("metric").get<std::string>(), metrics[i].at("statistic").get<std::string>()}] = i;
  }
  std::vector<const json*> kept;
  for (std::size_t i = 0; i < metrics.size(); ++i) {
    if (last.at({metrics[i].at("metric").get<std::string>(), metrics[i].at("statistic").get<std::string>()}) == i) {
      kept.push_back(&metrics[i]);
    }
  }
  return kept;
}

json ParseDocument(const std::filesystem::path& file, const std::string& run_id, const char* what,
                   const std::string& text) {
  json parsed = json::parse(text, nullptr, false);
  if (parsed.is_discarded()) {
    throw InputError(
        fmt::format("{}: run {}: its {} is not valid JSON; the database was edited or is damaged: "
                    "record the run again from its runs/ folder",
                    file.string(), run_id, what));
  }
  return parsed;
}

}  // namespace

std::string TypicalWallKey(const std::string& algorithm, const std::string& sequence) {
  return algorithm + "\t" + sequence;
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
    throw InputError(
        fmt::format("{}: results database schema version {} is newer than this slamsweep's ({}); "
                    "use a newer slamsweep or another output directory",
                    db_.file().string(), version, kResultsSchemaVersion));
  }
  if (version == 0 && tables > 0) {
    throw InputError(
        fmt::format("{}: an SQLite database but not a slamsweep results database (it has tables and "
                    "no schema version); use another output directory",
                    db_.file().string()));
  }
  // WAL lets readers (status, report) work while a sweep writes; it is a property of the file, kept once set.
  db_.ExecuteRetryingWhileBusy("PRAGMA journal_mode = WAL");
  db_.Execute("PRAGMA synchronous = NORMAL");
  if (version == kResultsSchemaVersion) return;
  SqliteTransaction transaction(db_);
  // Another process may have created or migrated the schema between the first read and the write lock.
  const std::int64_t locked_version = read_version();
  if (locked_version == kResultsSchemaVersion) {
    transaction.Commit();
    return;
  }
  CreateOrMigrateSchema(db_, locked_version, [this](const V3Run& run) {
    const RunFlags flags = run.flags ? RunFlagsFromText(*run.flags, db_.file().string() + ": runs.flags")
                                     : RunFlagsOf(run.spec, run.result);
    WriteRun(run.sweep_id, run.spec, run.result, run.run_dir, flags);
  });
  transaction.Commit();
}

void ResultsStore::RecordRun(std::int64_t sweep_id, const json& run_spec, const json& result,
                             const std::string& run_dir_relative) {
  const RunFlags flags = RunFlagsOf(run_spec, result);
  WriteInTransaction([&] { WriteRun(sweep_id, run_spec, result, run_dir_relative, flags); });
}

void ResultsStore::WriteInTransaction(const std::function<void()>& write) {
  try {
    if (batch_) {
      write();
      return;
    }
    SqliteTransaction transaction(db_);
    write();
    transaction.Commit();
  } catch (...) {
    // Rolled back (or about to be, with the batch): ids cached meanwhile may name rows that never were.
    metric_name_ids_.clear();
    document_ids_.clear();
    throw;
  }
}

void ResultsStore::BeginBatch() {
  if (batch_) throw InputError(db_.file().string() + ": a batch of writes is already open");
  batch_ = std::make_unique<SqliteTransaction>(db_);
}

void ResultsStore::CommitBatch() {
  if (!batch_) return;
  std::unique_ptr<SqliteTransaction> batch = std::move(batch_);
  try {
    batch->Commit();
  } catch (...) {
    metric_name_ids_.clear();
    document_ids_.clear();
    throw;
  }
}

SqliteStatement& ResultsStore::Cached(const std::string& sql) {
  std::unique_ptr<SqliteStatement>& statement = statements_[sql];
  if (!statement) statement = db_.PrepareKept(sql);
  statement->Reset();
  return *statement;
}

std::int64_t ResultsStore::Document(const json& value) {
  const std::string text = Dump(value);
  const auto digest = static_cast<std::int64_t>(Fnv1a64(text));
  if (const auto found = document_ids_.find(digest); found != document_ids_.end() && found->second.second == text) {
    return found->second.first;
  }
  const std::int64_t id = DocumentId(db_, value);
  document_ids_[digest] = {id, text};
  return id;
}

std::map<std::string, ResultsStore::RecordedIdentity> ResultsStore::RecordedIdentities() const {
  std::map<std::string, RecordedIdentity> identities;
  auto select = db_.Prepare("SELECT run_id, result_digest, flags, finished_at, run_dir FROM runs");
  while (select.Step()) {
    RecordedIdentity& identity = identities[select.Text(0)];
    identity.result_digest = static_cast<std::uint64_t>(select.Int64(1));
    identity.flags = RunFlagsFromText(NullableText(select, 2), db_.file().string() + ": runs.flags");
    identity.finished_at = NullableText(select, 3);
    identity.run_dir = NullableText(select, 4);
  }
  return identities;
}

void ResultsStore::ImportRun(std::int64_t sweep_id, const RunRecord& run, const std::string& run_dir_relative) {
  WriteInTransaction(
      [&] { WriteRun(sweep_id, run.run_spec, run.result, run_dir_relative, run.flags, run.result_digest); });
}

void ResultsStore::WriteRun(std::int64_t sweep_id, const json& run_spec, const json& result,
                            const std::string& run_dir_relative, const RunFlags& flags,
                            std::optional<std::uint64_t> result_digest) {
  const RunColumns columns = ValidateRun(run_spec, result);
  json spec_shared = run_spec;
  json spec_own = json::object();
  for (const char* key : kSpecOwnMembers) {
    if (const auto it = spec_shared.find(key); it != spec_shared.end()) {
      spec_own[key] = std::move(*it);
      spec_shared.erase(key);
    }
  }
  json result_shared = json::object();
  for (const char* key : kResultSharedMembers) {
    if (const json* value = FindField(result, key); value != nullptr) result_shared[key] = *value;
  }
  const std::int64_t spec_document = Document(spec_shared);
  const std::int64_t result_document = Document(result_shared);
  {
    // An earlier recording of this run id goes with its metric rows.
    for (const char* table : {"metric_values", "metric_spec_refs"}) {
      auto& remove = Cached(fmt::format("DELETE FROM {} WHERE run = (SELECT id FROM runs WHERE run_id = ?)", table));
      remove.Bind(1, columns.run_id);
      remove.Run();
    }
    auto& remove = Cached("DELETE FROM runs WHERE run_id = ?");
    remove.Bind(1, columns.run_id);
    remove.Run();
  }
  {
    auto& insert = Cached(
        "INSERT INTO runs(run_id, sweep_id, algorithm, adapter, parameters_json, sequence, noise, iteration, seed, "
        "status, failure_kind, reason, exit_code, signal, wall_s, cpu_s, peak_rss_kb, started_at, finished_at, "
        "run_dir, parameters, odometry_is_reference, seeding, slamsweep_revision, flags, spec_shared, spec_own, "
        "result_shared, result_digest) "
        "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
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
    insert.Bind(10, RunStatusName(columns.status));
    int index = 11;
    for (const char* key : kResultColumns) insert.BindJson(index++, FieldOrNull(result, key));
    insert.Bind(20, run_dir_relative);
    // Runs planned before run.json named its group: the text from their parameters.
    const json& group_parameters = Nested(run_spec, "group", "parameters");
    insert.BindJson(21, group_parameters.is_null() ? json(ParametersText(parameters)) : group_parameters);
    insert.BindJson(22, OdometryIsReferenceOf(run_spec, result));
    insert.BindJson(23, FieldOrNull(run_spec, "seeding"));
    insert.BindJson(24, Nested(run_spec, "build", "slamsweep_revision"));
    insert.Bind(25, RunFlagsText(flags));
    insert.Bind(26, spec_document).Bind(27, std::string_view(Dump(spec_own)));
    insert.Bind(28, result_document);
    insert.Bind(29, result_digest ? static_cast<std::int64_t>(*result_digest) : ResultDigest(result));
    insert.Run();
  }
  const std::int64_t run = db_.LastInsertRowId();
  if (mid_transaction_hook_) mid_transaction_hook_();
  if (const json* metrics = FindField(result, "metrics"); metrics != nullptr && metrics->is_array()) {
    auto& insert = Cached("INSERT INTO metric_values(run, position, name, value) VALUES(?, ?, ?, ?)");
    std::int64_t position = 0;
    for (const json* m : DistinctMetrics(*metrics)) {
      const json& unit = FieldOrNull(*m, "unit");
      const std::tuple<std::string, std::string, std::string> key{m->at("metric").get<std::string>(),
                                                                  m->at("statistic").get<std::string>(),
                                                                  unit.is_string() ? unit.get<std::string>() : ""};
      auto known = metric_name_ids_.find(key);
      if (known == metric_name_ids_.end()) {
        // Another process may have added it meanwhile: insert unless there, then read its id.
        auto& add = Cached("INSERT OR IGNORE INTO metric_names(metric, statistic, unit) VALUES(?, ?, ?)");
        add.Bind(1, std::get<0>(key)).Bind(2, std::get<1>(key)).Bind(3, std::get<2>(key));
        add.Run();
        auto& find = Cached("SELECT id FROM metric_names WHERE metric = ? AND statistic = ? AND unit = ?");
        find.Bind(1, std::get<0>(key)).Bind(2, std::get<1>(key)).Bind(3, std::get<2>(key));
        if (!find.Step()) throw InputError(db_.file().string() + ": metric name not recorded");
        known = metric_name_ids_.emplace(key, find.Int64(0)).first;
        // A statement left on a row keeps its read snapshot open, which would keep later writes (and a
        // table drop during a conversion) from starting.
        find.Reset();
      }
      insert.Reset();
      insert.Bind(1, run).Bind(2, position++).Bind(3, known->second).BindJson(4, FieldOrNull(*m, "value"));
      insert.Run();
    }
  }
  if (const json* details = FindField(result, "metric_details"); details != nullptr && details->is_object()) {
    auto& insert = Cached("INSERT INTO metric_spec_refs(run, metric, spec) VALUES(?, ?, ?)");
    for (const auto& [metric, detail] : details->items()) {
      const std::int64_t spec = Document(MetricSpecification(detail));
      insert.Reset();
      insert.Bind(1, run).Bind(2, metric).Bind(3, spec);
      insert.Run();
    }
  }
}

std::optional<RunStatus> ResultsStore::StatusOf(const std::string& run_id) const {
  auto select = db_.Prepare("SELECT status FROM runs WHERE run_id = ?");
  select.Bind(1, run_id);
  if (!select.Step()) return std::nullopt;
  return StoredRunStatus(db_.file(), run_id, select.Text(0));
}

std::optional<RunRecord> ResultsStore::FindRun(const std::string& run_id) const {
  std::vector<RunRecord> runs = QueryRuns("WHERE run_id = ?1", run_id);
  if (runs.empty()) return std::nullopt;
  return std::move(runs.front());
}

std::vector<RunRecord> ResultsStore::Runs() const { return QueryRuns("", ""); }

bool ResultsStore::AddRunFlags(const std::string& run_id, const RunFlags& added) {
  SqliteTransaction transaction(db_);
  auto select = db_.Prepare("SELECT flags FROM runs WHERE run_id = ?");
  select.Bind(1, run_id);
  if (!select.Step()) return false;
  RunFlags flags = RunFlagsFromText(select.IsNull(0) ? "" : select.Text(0), db_.file().string() + ": runs.flags");
  flags |= added;
  auto update = db_.Prepare("UPDATE runs SET flags = ? WHERE run_id = ?");
  update.Bind(1, RunFlagsText(flags)).Bind(2, run_id);
  update.Run();
  transaction.Commit();
  return true;
}

std::vector<RunRecord> ResultsStore::QueryRuns(const std::string& where, const std::string& run_id) const {
  std::vector<RunRecord> runs;
  std::unordered_map<std::int64_t, std::size_t> index_of;
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
  // Documents are shared by many runs: each is parsed once.
  std::unordered_map<std::string, json> parsed_documents;
  const auto document = [&](const std::string& text, const std::string& id, const char* what) -> const json& {
    auto it = parsed_documents.find(text);
    if (it == parsed_documents.end())
      it = parsed_documents.emplace(text, ParseDocument(db_.file(), id, what, text)).first;
    return it->second;
  };
  {
    auto select =
        db_.Prepare(fmt::format("SELECT {} FROM runs JOIN documents AS spec_doc ON spec_doc.id = runs.spec_shared "
                                "JOIN documents AS result_doc ON result_doc.id = runs.result_shared {} "
                                "ORDER BY sequence, algorithm, noise, iteration, run_id",
                                kRunColumns, where));
    if (!where.empty()) select.Bind(1, run_id);
    while (select.Step()) {
      RunRecord run;
      const std::int64_t id = select.Int64(0);
      run.run_id = select.Text(1);
      run.sweep_id = select.Int64(2);
      run.status = StoredRunStatus(db_.file(), run.run_id, select.Text(3));
      run.run_dir = NullableText(select, 4);
      run.algorithm = NullableText(select, 5);
      run.sequence = NullableText(select, 6);
      run.noise = NullableText(select, 7);
      run.iteration = static_cast<int>(select.Int64(8));
      run.wall_s = select.OptionalDouble(9);
      run.finished_at = NullableText(select, 10);
      run.parameters = NullableText(select, 11);
      run.odometry_is_reference = !select.IsNull(12) && select.Int64(12) != 0;
      run.seeding = NullableText(select, 13);
      run.flags = RunFlagsFromText(NullableText(select, 14), db_.file().string() + ": runs.flags");
      run.run_spec = document(select.Text(16), run.run_id, "run.json");
      run.run_spec.update(ParseDocument(db_.file(), run.run_id, "run.json", select.Text(15)));
      run.result = document(select.Text(17), run.run_id, "result.json");
      run.result_digest = static_cast<std::uint64_t>(select.Int64(18));
      run.result["run_id"] = run.run_id;
      run.result["status"] = std::string(RunStatusName(run.status));
      for (int i = 0; i < static_cast<int>(std::size(kResultColumns)); ++i) {
        run.result[kResultColumns[i]] = select.Json(kResultColumnIndex[i]);
      }
      run.result["flags"] = ToJson(run.flags);
      FillResultFields(run);
      run.result["metrics"] = json::array();
      run.result["metric_details"] = json::object();
      index_of.emplace(id, runs.size());
      runs.push_back(std::move(run));
    }
  }
  const std::string run_filter = where.empty() ? "" : "WHERE runs.run_id = ?1";
  auto metrics = db_.Prepare(fmt::format(
      "SELECT metric_values.run, metric, statistic, value, unit FROM metric_values "
      "JOIN metric_names ON metric_names.id = metric_values.name JOIN runs ON runs.id = metric_values.run {} "
      "ORDER BY metric_values.run, position",
      run_filter));
  if (!where.empty()) metrics.Bind(1, run_id);
  while (metrics.Step()) {
    const auto it = index_of.find(metrics.Int64(0));
    if (it == index_of.end()) continue;
    RunRecord& run = runs[it->second];
    FlatMetric metric{metrics.Text(1), metrics.Text(2), metrics.OptionalDouble(3), metrics.Text(4)};
    run.result["metrics"].push_back({{"metric", metric.metric},
                                     {"statistic", metric.statistic},
                                     {"value", metric.value ? json(*metric.value) : json(nullptr)},
                                     {"unit", metric.unit.empty() ? json(nullptr) : json(metric.unit)}});
    run.metrics.push_back(std::move(metric));
  }
  auto specs = db_.Prepare(fmt::format(
      "SELECT metric_spec_refs.run, metric, documents.json FROM metric_spec_refs "
      "JOIN documents ON documents.id = metric_spec_refs.spec JOIN runs ON runs.id = metric_spec_refs.run {}",
      run_filter));
  if (!where.empty()) specs.Bind(1, run_id);
  while (specs.Step()) {
    const auto it = index_of.find(specs.Int64(0));
    if (it == index_of.end()) continue;
    RunRecord& run = runs[it->second];
    run.result["metric_details"][specs.Text(1)] = document(specs.Text(2), run.run_id, "metric specification");
  }
  return runs;
}

std::map<std::string, double> ResultsStore::TypicalWallSeconds() const {
  auto select = db_.Prepare("SELECT algorithm, sequence, wall_s FROM runs WHERE status = ? AND wall_s IS NOT NULL");
  select.Bind(1, RunStatusName(RunStatus::kOk));
  std::map<std::string, std::vector<double>> walls;
  while (select.Step()) {
    walls[TypicalWallKey(NullableText(select, 0), NullableText(select, 1))].push_back(select.Double(2));
  }
  std::map<std::string, double> typical;
  for (auto& [key, values] : walls) typical.emplace(key, Median(std::move(values)));
  return typical;
}

}  // namespace slamsweep::orchestrator
