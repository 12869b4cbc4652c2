#include "orchestrator/store/run_reader.h"

#include <cstdint>
#include <exception>
#include <filesystem>
#include <unordered_map>
#include <utility>

#include <fmt/format.h>

#include "orchestrator/run/run_flags.h"
#include "orchestrator/run/run_status.h"
#include "orchestrator/store/runs_table.h"

namespace slamsweep::orchestrator::inline store {
namespace {

using nlohmann::json;

// Documents are shared by many runs: each is parsed once.
class ParsedDocuments {
 public:
  explicit ParsedDocuments(const std::filesystem::path& file) : file_(file) {}

  const json& Get(const std::string& text, const std::string& run_id, const char* what) {
    auto it = parsed_.find(text);
    if (it == parsed_.end()) it = parsed_.emplace(text, ParseStoredDocument(file_, run_id, what, text)).first;
    return it->second;
  }

 private:
  const std::filesystem::path& file_;
  std::unordered_map<std::string, json> parsed_;
};

// A row of kRunColumns as a record whose result.json has every member but its metrics and metric details
// (empty until their rows are read).
RunRecord RunFromRow(const SqliteStatement& select, const std::filesystem::path& file, ParsedDocuments& documents) {
  RunRecord run;
  run.run_id = select.Text(1);
  run.sweep_id = select.Int64(2);
  run.status = StoredRunStatus(file, run.run_id, select.Text(3));
  run.run_dir = select.TextOrEmpty(4);
  run.algorithm = select.TextOrEmpty(5);
  run.sequence = select.TextOrEmpty(6);
  run.noise = select.TextOrEmpty(7);
  run.iteration = static_cast<int>(select.Int64(8));
  run.wall_s = select.OptionalDouble(9);
  run.finished_at = select.TextOrEmpty(10);
  run.parameters = select.TextOrEmpty(11);
  run.odometry_is_reference = !select.IsNull(12) && select.Int64(12) != 0;
  run.seeding = select.TextOrEmpty(13);
  run.flags = RunFlagsFromText(select.TextOrEmpty(14), file.string() + ": runs.flags");
  run.run_spec = documents.Get(select.Text(16), run.run_id, "run.json");
  run.run_spec.update(ParseStoredDocument(file, run.run_id, "run.json", select.Text(15)));
  run.result = documents.Get(select.Text(17), run.run_id, "result.json");
  run.result_digest = static_cast<std::uint64_t>(select.Int64(18));
  run.result["run_id"] = run.run_id;
  run.result["status"] = std::string(RunStatusName(run.status));
  for (int i = 0; i < static_cast<int>(std::size(kResultColumns)); ++i) {
    run.result[kResultColumns[i]] = select.Json(kResultColumnIndex[i]);
  }
  run.result["flags"] = ToJson(run.flags);
  ReadResultFields(run.result, run);
  run.result["metrics"] = json::array();
  run.result["metric_details"] = json::object();
  return run;
}

// The runs `where` selects (empty: all), `run_id` bound to its ?1.
std::vector<RunRecord> QueryRuns(const SqliteDb& db, const std::string& where, const std::string& run_id) {
  std::vector<RunRecord> runs;
  std::unordered_map<std::int64_t, std::size_t> index_of;
  // Both reads see one snapshot, so a concurrent RecordRun cannot pair a run with another version's metrics.
  SqliteStatement begin = db.Prepare("BEGIN");
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
  } end_read{db};
  ParsedDocuments documents(db.file());
  {
    auto select =
        db.Prepare(fmt::format("SELECT {} FROM runs JOIN documents AS spec_doc ON spec_doc.id = runs.spec_shared "
                               "JOIN documents AS result_doc ON result_doc.id = runs.result_shared {} "
                               "ORDER BY sequence, algorithm, noise, iteration, run_id",
                               kRunColumns, where));
    if (!where.empty()) select.Bind(1, run_id);
    while (select.Step()) {
      index_of.emplace(select.Int64(0), runs.size());
      runs.push_back(RunFromRow(select, db.file(), documents));
    }
  }
  const std::string run_filter = where.empty() ? "" : "WHERE runs.run_id = ?1";
  auto metrics = db.Prepare(fmt::format(
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
  auto specs = db.Prepare(fmt::format(
      "SELECT metric_spec_refs.run, metric, documents.json FROM metric_spec_refs "
      "JOIN documents ON documents.id = metric_spec_refs.spec JOIN runs ON runs.id = metric_spec_refs.run {}",
      run_filter));
  if (!where.empty()) specs.Bind(1, run_id);
  while (specs.Step()) {
    const auto it = index_of.find(specs.Int64(0));
    if (it == index_of.end()) continue;
    RunRecord& run = runs[it->second];
    run.result["metric_details"][specs.Text(1)] = documents.Get(specs.Text(2), run.run_id, "metric specification");
  }
  return runs;
}

}  // namespace

std::vector<RunRecord> ReadRuns(const SqliteDb& db) { return QueryRuns(db, "", ""); }

std::optional<RunRecord> ReadRun(const SqliteDb& db, const std::string& run_id) {
  std::vector<RunRecord> runs = QueryRuns(db, "WHERE run_id = ?1", run_id);
  if (runs.empty()) return std::nullopt;
  return std::move(runs.front());
}

}  // namespace slamsweep::orchestrator::inline store
