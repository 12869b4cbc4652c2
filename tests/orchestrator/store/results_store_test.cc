#include "orchestrator/store/results_store.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/store/sqlite_db.h"
#include "tests/orchestrator/store/store_test_util.h"
#include "tests/support/shared_data.h"
#include "tests/support/input_error_text.h"

namespace slamsweep::orchestrator {
namespace {

using evaluator::InputError;
using ::testing::HasSubstr;
using testing::MakeFailedResult;
using testing::MakeOkResult;
using testing::MakeSpec;

using slamsweep::testing::ErrorOf;

std::int64_t QueryInt(const std::filesystem::path& file, const std::string& sql) {
  SqliteDb db = SqliteDb::Open(file, false);
  auto statement = db.Prepare(sql);
  EXPECT_TRUE(statement.Step()) << sql;
  return statement.Int64(0);
}

TEST(ResultsStoreTest, CreatesSchemaAndReopens) {
  slamsweep::testing::TempDir dir;
  const auto file = dir / "results.sqlite";
  {
    ResultsStore store = ResultsStore::Open(file);
    SweepInfo info;
    info.name = "quick";
    info.config_sha = "abc";
    info.host = "node1";
    const std::int64_t sweep = store.BeginSweep(info);
    store.RecordRun(sweep, MakeSpec("r1"), MakeOkResult("r1"), "runs/r1");
    store.FinishSweep(sweep, SweepStatus::kOk, 1);
  }
  EXPECT_EQ(QueryInt(file, "PRAGMA user_version"), kResultsSchemaVersion);
  EXPECT_EQ(QueryInt(file,
                     "SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name IN "
                     "('sweeps', 'runs', 'documents', 'metric_names', 'metric_values', 'metric_spec_refs')"),
            6);
  // The queries of the tables of schema versions 1-3 still work, as views.
  EXPECT_EQ(QueryInt(file,
                     "SELECT count(*) FROM sqlite_master WHERE type = 'view' AND name IN "
                     "('metrics', 'metric_specs')"),
            2);
  EXPECT_EQ(QueryInt(file,
                     "SELECT count(*) FROM sqlite_master WHERE type = 'index' AND sql LIKE "
                     "'%(algorithm, sequence)%'"),
            1);
  {
    SqliteDb db = SqliteDb::Open(file, false);
    auto mode = db.Prepare("PRAGMA journal_mode");
    ASSERT_TRUE(mode.Step());
    EXPECT_EQ(mode.Text(0), "wal");
  }
  ResultsStore reopened = ResultsStore::Open(file);
  EXPECT_EQ(reopened.StatusOf("r1"), RunStatus::kOk);
  EXPECT_EQ(reopened.StatusOf("nope"), std::nullopt);
  const auto sweeps = reopened.Sweeps();
  ASSERT_EQ(sweeps.size(), 1u);
  EXPECT_EQ(sweeps[0].info.name, "quick");
  EXPECT_EQ(sweeps[0].status, SweepStatus::kOk);
  EXPECT_EQ(sweeps[0].run_count, 1);
  EXPECT_FALSE(sweeps[0].info.started_at.empty());
  EXPECT_FALSE(sweeps[0].finished_at.empty());
}

TEST(ResultsStoreTest, RunsCarryColumnsSpecResultAndMetrics) {
  slamsweep::testing::TempDir dir;
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  const auto spec = MakeSpec("r1", "icp-slam", "intel", 2);
  const auto result = MakeOkResult("r1", 4.5);
  store.RecordRun(7, spec, result, "runs/r1");
  store.RecordRun(7, MakeSpec("r2", "icp-slam", "fr079"), MakeFailedResult("r2"), "runs/r2");
  const auto runs = store.Runs();
  ASSERT_EQ(runs.size(), 2u);
  // Ordered by sequence first: fr079 < intel.
  EXPECT_EQ(runs[0].run_id, "r2");
  EXPECT_EQ(runs[0].status, RunStatus::kFailed);
  EXPECT_TRUE(runs[0].metrics.empty());
  const RunRecord& r1 = runs[1];
  EXPECT_EQ(r1.sweep_id, 7);
  EXPECT_EQ(r1.run_spec, spec);
  // result.json's columns, command, outputs and warnings come back; of metric_details only how each metric
  // was specified (the run folder keeps the rest).
  for (const char* key : {"run_id", "status", "failure_kind", "reason", "exit_code", "signal", "wall_s", "cpu_s",
                          "peak_rss_kb", "started_at", "finished_at", "outputs", "warnings"}) {
    EXPECT_EQ(r1.result.at(key), result.at(key)) << key;
  }
  EXPECT_EQ(r1.result.at("flags"), nlohmann::json::array());
  EXPECT_EQ(r1.result.at("metric_details"), (nlohmann::json{{"ape_trans", nlohmann::json::object()}}));
  EXPECT_EQ(r1.result.at("metrics").size(), 3u);
  EXPECT_EQ(r1.algorithm, "icp-slam");
  EXPECT_EQ(r1.sequence, "intel");
  EXPECT_EQ(r1.noise, "clean");
  EXPECT_EQ(r1.iteration, 2);
  EXPECT_EQ(r1.run_dir, "runs/r1");
  EXPECT_EQ(r1.wall_s, 4.5);
  EXPECT_EQ(r1.finished_at, "2026-11-22T05:00:03Z");
  ASSERT_EQ(r1.metrics.size(), 3u);
  EXPECT_EQ(r1.metrics[0].metric, "ape_trans");
  EXPECT_EQ(r1.metrics[0].statistic, "rmse");
  EXPECT_EQ(r1.metrics[0].value, 0.12);
  EXPECT_EQ(r1.metrics[0].unit, "m");
  EXPECT_EQ(r1.metrics[2].metric, "corners");
  EXPECT_EQ(r1.metrics[2].value, 17.0);
  const auto found = store.FindRun("r1");
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->metrics.size(), 3u);
  EXPECT_EQ(QueryInt(dir / "results.sqlite", "SELECT count(*) FROM metric_specs WHERE run_id = 'r1'"), 1);
  EXPECT_EQ(QueryInt(dir / "results.sqlite", "SELECT count(*) FROM metrics WHERE run_id = 'r1'"), 3);
  EXPECT_EQ(QueryInt(dir / "results.sqlite", "SELECT seed FROM runs WHERE run_id = 'r1'"), 123456789);
}

TEST(ResultsStoreTest, WhatRunsShareIsKeptOnceAndTheMetricSpecificationWithoutTheNumbers) {
  slamsweep::testing::TempDir dir;
  const auto file = dir / "results.sqlite";
  ResultsStore store = ResultsStore::Open(file);
  nlohmann::json result = MakeOkResult("r0");
  result["metric_details"] = {
      {"ape_trans", {{"rmse", 0.12}, {"specification", {{"alignment", "se2"}, {"t_max_diff_s", 0.01}}}}},
      {"paper_map", {{"corners", 17}, {"parameters", {{"occupied_threshold", 0.65}}}}}};
  for (int i = 0; i < 20; ++i) {
    const std::string id = fmt::format("r{}", i);
    result["run_id"] = id;
    result["metric_details"]["ape_trans"]["rmse"] = 0.1 + 0.01 * i;
    store.RecordRun(1, MakeSpec(id, "icp-slam", "intel", i), result, "runs/" + id);
  }
  // One document for the runs' shared run.json, one for their command/outputs/warnings, one per distinct
  // metric specification.
  EXPECT_EQ(QueryInt(file, "SELECT count(*) FROM documents"), 4);
  EXPECT_EQ(QueryInt(file, "SELECT count(*) FROM metric_names"), 3);
  EXPECT_EQ(QueryInt(file, "SELECT count(*) FROM metric_values"), 60);
  SqliteDb db = SqliteDb::Open(file, false);
  auto spec = db.Prepare("SELECT spec_json FROM metric_specs WHERE run_id = 'r7' AND metric = 'ape_trans'");
  ASSERT_TRUE(spec.Step());
  EXPECT_EQ(nlohmann::json::parse(spec.Text(0)),
            (nlohmann::json{{"specification", {{"alignment", "se2"}, {"t_max_diff_s", 0.01}}}}));
  const std::optional<RunRecord> r7 = store.FindRun("r7");
  ASSERT_TRUE(r7.has_value());
  EXPECT_EQ(r7->run_spec, MakeSpec("r7", "icp-slam", "intel", 7));
  EXPECT_EQ(r7->result.at("metric_details").at("paper_map"),
            (nlohmann::json{{"parameters", {{"occupied_threshold", 0.65}}}}));
}

TEST(ResultsStoreTest, ResultDigestTellsRecordingsApartButNotTheirFlags) {
  slamsweep::testing::TempDir dir;
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  store.RecordRun(1, MakeSpec("a"), MakeOkResult("a", 3.0), "runs/a");
  store.RecordRun(1, MakeSpec("b"), MakeOkResult("b", 3.0), "runs/b");
  const std::uint64_t a = store.FindRun("a")->result_digest;
  // Another run id is another text.
  EXPECT_NE(store.FindRun("b")->result_digest, a);
  nlohmann::json flagged = MakeOkResult("a", 3.0);
  flagged["flags"] = {"stale"};
  store.RecordRun(1, MakeSpec("a"), flagged, "runs/a");
  EXPECT_EQ(store.FindRun("a")->result_digest, a);
  store.RecordRun(1, MakeSpec("a"), MakeOkResult("a", 3.5), "runs/a");
  EXPECT_NE(store.FindRun("a")->result_digest, a);
  // A run imported into another store keeps its digest and flags.
  ResultsStore other = ResultsStore::Open(dir / "other.sqlite");
  const RunRecord b = *store.FindRun("b");
  other.ImportRun(1, b, "runs/b");
  EXPECT_EQ(other.FindRun("b")->result_digest, b.result_digest);
  EXPECT_EQ(other.FindRun("b")->run_spec, b.run_spec);
  EXPECT_EQ(other.FindRun("b")->metrics.size(), b.metrics.size());
}

TEST(ResultsStoreTest, RecordRunReplacesTheRunAndAllItsMetrics) {
  slamsweep::testing::TempDir dir;
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  store.RecordRun(1, MakeSpec("r1"), MakeOkResult("r1"), "runs/r1");
  auto second = MakeOkResult("r1", 9.0, 0.5);
  second["metrics"] = {{{"metric", "rpe_rot"}, {"statistic", "max"}, {"value", 2.0}, {"unit", "deg"}}};
  second["metric_details"] = nlohmann::json::object();
  store.RecordRun(1, MakeSpec("r1"), second, "runs/r1");
  const auto run = store.FindRun("r1");
  ASSERT_TRUE(run.has_value());
  ASSERT_EQ(run->metrics.size(), 1u);
  EXPECT_EQ(run->metrics[0].metric, "rpe_rot");
  EXPECT_EQ(run->wall_s, 9.0);
  EXPECT_EQ(store.Runs().size(), 1u);
  EXPECT_EQ(QueryInt(dir / "results.sqlite", "SELECT count(*) FROM metrics"), 1);
  EXPECT_EQ(QueryInt(dir / "results.sqlite", "SELECT count(*) FROM metric_specs"), 0);
  // No row of the earlier recording is left behind, not even one no run refers to.
  EXPECT_EQ(QueryInt(dir / "results.sqlite", "SELECT count(*) FROM metric_values"), 1);
  EXPECT_EQ(QueryInt(dir / "results.sqlite", "SELECT count(*) FROM metric_spec_refs"), 0);
  // A failed re-run leaves no metrics of the earlier ok run behind.
  store.RecordRun(1, MakeSpec("r1"), MakeFailedResult("r1"), "runs/r1");
  EXPECT_EQ(store.StatusOf("r1"), RunStatus::kFailed);
  EXPECT_TRUE(store.FindRun("r1")->metrics.empty());
}

TEST(ResultsStoreTest, NullMetricValuesAndHugeSeedsSurvive) {
  slamsweep::testing::TempDir dir;
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  auto spec = MakeSpec("r1");
  spec["seed"] = 18446744073709551615ull;
  auto result = MakeOkResult("r1");
  result["metrics"] = {{{"metric", "ape_rot"}, {"statistic", "std"}, {"value", nullptr}, {"unit", "deg"}}};
  store.RecordRun(1, spec, result, "runs/r1");
  const auto run = store.FindRun("r1");
  ASSERT_EQ(run->metrics.size(), 1u);
  EXPECT_FALSE(run->metrics[0].value.has_value());
  EXPECT_EQ(run->run_spec.at("seed").get<std::uint64_t>(), 18446744073709551615ull);
  SqliteDb db = SqliteDb::Open(dir / "results.sqlite", false);
  auto seed = db.Prepare("SELECT seed FROM runs");
  ASSERT_TRUE(seed.Step());
  EXPECT_EQ(seed.Text(0), "18446744073709551615");
}

TEST(ResultsStoreTest, TypicalWallSecondsIsTheMedianOfOkRuns) {
  slamsweep::testing::TempDir dir;
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  // icp-slam on intel: 1, 10, 3 -> median 3; on fr079: 2, 4 -> mean of the middle two = 3.
  store.RecordRun(1, MakeSpec("a", "icp-slam", "intel", 0), MakeOkResult("a", 1.0), "runs/a");
  store.RecordRun(1, MakeSpec("b", "icp-slam", "intel", 1), MakeOkResult("b", 10.0), "runs/b");
  store.RecordRun(1, MakeSpec("c", "icp-slam", "intel", 2), MakeOkResult("c", 3.0), "runs/c");
  store.RecordRun(1, MakeSpec("d", "icp-slam", "fr079", 0), MakeOkResult("d", 2.0), "runs/d");
  store.RecordRun(1, MakeSpec("e", "icp-slam", "fr079", 1), MakeOkResult("e", 4.0), "runs/e");
  // Failed runs (often timeouts) say nothing about the typical duration.
  auto failed = MakeFailedResult("f");
  failed["wall_s"] = 1000.0;
  store.RecordRun(1, MakeSpec("f", "icp-slam", "fr079", 2), failed, "runs/f");
  failed["run_id"] = "g";
  store.RecordRun(1, MakeSpec("g", "rbpf", "fr079", 2), failed, "runs/g");
  const auto typical = store.TypicalWallSeconds();
  ASSERT_EQ(typical.size(), 2u);
  EXPECT_DOUBLE_EQ(typical.at(TypicalWallKey("icp-slam", "intel")), 3.0);
  EXPECT_DOUBLE_EQ(typical.at("icp-slam\tfr079"), 3.0);
}

TEST(ResultsStoreTest, BadRunInputNamesTheField) {
  slamsweep::testing::TempDir dir;
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  auto no_id = MakeSpec("r1");
  no_id.erase("run_id");
  EXPECT_THAT(ErrorOf([&] { store.RecordRun(1, no_id, MakeOkResult("r1"), "runs/r1"); }),
              HasSubstr("run.json: run_id: expected a non-empty string"));
  auto bad_status = MakeOkResult("r1");
  bad_status["status"] = "great";
  EXPECT_THAT(ErrorOf([&] { store.RecordRun(1, MakeSpec("r1"), bad_status, "runs/r1"); }),
              HasSubstr("result.json of run r1: status: expected \"ok\" or \"failed\", found \"great\""));
  EXPECT_THAT(ErrorOf([&] { store.RecordRun(1, MakeSpec("r1"), MakeOkResult("other"), "runs/r1"); }),
              HasSubstr("run_id: expected \"r1\""));
  auto bad_metric = MakeOkResult("r1");
  bad_metric["metrics"][1]["value"] = "high";
  EXPECT_THAT(ErrorOf([&] { store.RecordRun(1, MakeSpec("r1"), bad_metric, "runs/r1"); }),
              HasSubstr("metrics[1].value: expected a number or null"));
  auto no_statistic = MakeOkResult("r1");
  no_statistic["metrics"][0].erase("statistic");
  EXPECT_THAT(ErrorOf([&] { store.RecordRun(1, MakeSpec("r1"), no_statistic, "runs/r1"); }),
              HasSubstr("metrics[0].statistic: expected a non-empty string"));
  EXPECT_THAT(ErrorOf([&] { store.RecordRun(1, nlohmann::json::array(), MakeOkResult("r1"), "runs/r1"); }),
              HasSubstr("run.json: expected a JSON object"));
  // Nothing half-recorded.
  EXPECT_TRUE(store.Runs().empty());
}

TEST(ResultsStoreTest, CorruptFileIsAnErrorNamingTheFileAndWhatToDo) {
  slamsweep::testing::TempDir dir;
  const auto file = slamsweep::testing::WriteFile(dir / "results.sqlite", std::string(8192, 'x'));
  const std::string error = ErrorOf([&] { ResultsStore::Open(file); });
  EXPECT_THAT(error, HasSubstr(file.string()));
  EXPECT_THAT(error, HasSubstr("not a database"));
  EXPECT_THAT(error, HasSubstr("move it away"));
}

TEST(ResultsStoreTest, DamagedDatabasePagesAreAnError) {
  slamsweep::testing::TempDir dir;
  const auto file = dir / "results.sqlite";
  {
    ResultsStore store = ResultsStore::Open(file);
    for (int i = 0; i < 50; ++i) {
      const std::string id = fmt::format("r{}", i);
      store.RecordRun(1, MakeSpec(id), MakeOkResult(id), fmt::format("runs/{}", id));
    }
  }
  // Keep the 100-byte header valid, overwrite the rest of every page with garbage.
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  ASSERT_GT(bytes.size(), 4096u);
  for (std::size_t i = 100; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 131) & 0xff);
  slamsweep::testing::WriteFile(file, bytes);
  const std::string error = ErrorOf([&] { ResultsStore::Open(file).Runs(); });
  EXPECT_THAT(error, HasSubstr(file.string()));
  EXPECT_THAT(error, ::testing::AnyOf(HasSubstr("malformed"), HasSubstr("not a database")));
}

TEST(ResultsStoreTest, NewerSchemaVersionIsRefused) {
  slamsweep::testing::TempDir dir;
  const auto file = dir / "results.sqlite";
  { ResultsStore::Open(file); }
  { SqliteDb::Open(file, false).Execute("PRAGMA user_version = 99"); }
  const std::string error = ErrorOf([&] { ResultsStore::Open(file); });
  EXPECT_THAT(error, HasSubstr(file.string()));
  EXPECT_THAT(error, HasSubstr("schema version 99 is newer"));
}

TEST(ResultsStoreTest, ForeignSqliteDatabaseIsRefused) {
  slamsweep::testing::TempDir dir;
  const auto file = dir / "other.sqlite";
  { SqliteDb::Open(file, true).Execute("CREATE TABLE photos(id INTEGER)"); }
  EXPECT_THAT(ErrorOf([&] { ResultsStore::Open(file); }), HasSubstr("not a slamsweep results database"));
}

TEST(ResultsStoreTest, OpenExistingRefusesMissingFile) {
  slamsweep::testing::TempDir dir;
  const auto file = dir / "results.sqlite";
  EXPECT_THAT(ErrorOf([&] { ResultsStore::OpenExisting(file); }), HasSubstr(file.string() + ": no such"));
  EXPECT_FALSE(std::filesystem::exists(file));
}

TEST(ResultsStoreTest, ImportSweepReusesAnIdenticalSweep) {
  slamsweep::testing::TempDir dir;
  ResultsStore store = ResultsStore::Open(dir / "results.sqlite");
  StoredSweep sweep;
  sweep.id = 42;
  sweep.info.name = "s";
  sweep.info.config_sha = "x";
  sweep.info.started_at = "2026-01-01T00:00:00Z";
  sweep.finished_at = "2026-01-01T01:00:00Z";
  sweep.status = SweepStatus::kOk;
  sweep.run_count = 3;
  const std::int64_t first = store.ImportSweep(sweep);
  EXPECT_EQ(store.ImportSweep(sweep), first);
  sweep.info.host = "other";
  EXPECT_NE(store.ImportSweep(sweep), first);
  EXPECT_EQ(store.Sweeps().size(), 2u);
  EXPECT_EQ(store.Sweeps()[0].run_count, 3);
}

TEST(ResultsStoreTest, RunFlagsAreRecordedAddedAndReadBack) {
  slamsweep::testing::TempDir dir;
  const auto file = dir / "results.sqlite";
  ResultsStore store = ResultsStore::Open(file);
  const std::int64_t sweep = store.BeginSweep(SweepInfo{});
  nlohmann::json result = MakeOkResult("r1");
  result["flags"] = {"unisolated"};
  nlohmann::json spec = MakeSpec("r1");
  spec["odometry_is_reference"] = true;
  store.RecordRun(sweep, spec, result, "runs/r1");
  store.RecordRun(sweep, MakeSpec("r2"), MakeOkResult("r2"), "runs/r2");
  EXPECT_EQ(store.FindRun("r1")->flags, (RunFlags{RunFlag::kOdometryIsReference, RunFlag::kUnisolated}));
  EXPECT_TRUE(store.FindRun("r2")->flags.empty());

  EXPECT_TRUE(store.AddRunFlags("r2", RunFlags{RunFlag::kStale}));
  EXPECT_FALSE(store.AddRunFlags("nope", RunFlags{RunFlag::kStale}));
  const std::optional<RunRecord> stale = store.FindRun("r2");
  EXPECT_EQ(stale->flags, RunFlags{RunFlag::kStale});
  EXPECT_EQ(stale->result.at("flags"), nlohmann::json::array({"stale"}));
  SqliteDb db = SqliteDb::Open(file, false);
  auto column = db.Prepare("SELECT flags FROM runs WHERE run_id = 'r1'");
  ASSERT_TRUE(column.Step());
  EXPECT_EQ(column.Text(0), "odometry_is_reference;unisolated");
}

// A results.sqlite as slamsweep wrote it with schema version 2 (version 1's tables plus the columns of
// version 2), holding one run whose run.json says its odometry was the reference.
void WriteVersion2Store(const std::filesystem::path& file) {
  SqliteDb db = SqliteDb::Open(file, true);
  db.Execute(R"sql(
CREATE TABLE sweeps(id INTEGER PRIMARY KEY, name TEXT, config_path TEXT, config_sha TEXT, started_at TEXT,
  finished_at TEXT, status TEXT, host TEXT, slamsweep_version TEXT, run_count INTEGER, command_line TEXT);
CREATE TABLE runs(run_id TEXT PRIMARY KEY, sweep_id INTEGER, algorithm TEXT, adapter TEXT, parameters_json TEXT,
  sequence TEXT, noise TEXT, iteration INTEGER, seed, spec_json TEXT NOT NULL,
  status TEXT NOT NULL CHECK(status IN ('ok', 'failed')), failure_kind TEXT, reason TEXT, exit_code INTEGER,
  signal INTEGER, wall_s REAL, cpu_s REAL, peak_rss_kb INTEGER, started_at TEXT, finished_at TEXT, run_dir TEXT,
  result_json TEXT NOT NULL, parameters TEXT, odometry_is_reference INTEGER, seeding TEXT, slamsweep_revision TEXT);
CREATE INDEX runs_algorithm_sequence ON runs(algorithm, sequence);
CREATE INDEX runs_sequence_algorithm ON runs(sequence, algorithm);
CREATE INDEX runs_group ON runs(sequence, noise, algorithm, parameters);
CREATE TABLE metrics(run_id TEXT NOT NULL, metric TEXT NOT NULL, statistic TEXT NOT NULL, value REAL, unit TEXT,
  PRIMARY KEY(run_id, metric, statistic));
CREATE TABLE metric_specs(run_id TEXT NOT NULL, metric TEXT NOT NULL, spec_json TEXT, PRIMARY KEY(run_id, metric));
INSERT INTO sweeps(id, name, status) VALUES(3, 'old', 'ok');
PRAGMA user_version = 2;
)sql");
  nlohmann::json spec = MakeSpec("old");
  spec["odometry_is_reference"] = true;
  auto insert = db.Prepare(
      "INSERT INTO runs(run_id, sweep_id, algorithm, sequence, noise, iteration, spec_json, status, wall_s, "
      "run_dir, result_json) VALUES('old', 3, 'icp-slam', 'intel', 'clean', 0, ?, 'ok', 3.0, 'runs/old', ?)");
  insert.Bind(1, std::string_view(spec.dump())).Bind(2, std::string_view(MakeOkResult("old").dump()));
  insert.Run();
  db.Execute("INSERT INTO metrics VALUES('old', 'ape_trans', 'rmse', 0.12, 'm')");
}

TEST(ResultsStoreTest, AVersion2StoreIsConvertedAndDerivesFlagsFromItsRuns) {
  slamsweep::testing::TempDir dir;
  const auto file = dir / "results.sqlite";
  WriteVersion2Store(file);
  ResultsStore reopened = ResultsStore::Open(file);
  EXPECT_EQ(QueryInt(file, "PRAGMA user_version"), kResultsSchemaVersion);
  const std::optional<RunRecord> old = reopened.FindRun("old");
  ASSERT_TRUE(old.has_value());
  EXPECT_EQ(old->sweep_id, 3);
  EXPECT_EQ(old->flags, RunFlags{RunFlag::kOdometryIsReference});
  EXPECT_EQ(old->run_dir, "runs/old");
  EXPECT_EQ(old->wall_s, 3.0);
  // The metrics come from the recorded result.json, as when the run was recorded.
  ASSERT_EQ(old->metrics.size(), 3u);
  EXPECT_EQ(old->metrics[2].metric, "corners");
  EXPECT_EQ(old->parameters, "ICP.maxIterations=80");
  EXPECT_EQ(QueryInt(file, "SELECT count(*) FROM sqlite_master WHERE name = 'runs_v3'"), 0);
  // Reopening a converted store changes nothing.
  const std::uint64_t digest = old->result_digest;
  EXPECT_EQ(ResultsStore::Open(file).FindRun("old")->result_digest, digest);
}

}  // namespace
}  // namespace slamsweep::orchestrator
