// A version 1 history (series keyed by algorithm x sequence x noise) opened by this build: every row is kept and
// gets the odometry mode its night's result directory says, or "unknown" when it cannot say.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "orchestrator/history/history_store.h"
#include "orchestrator/history/regression.h"
#include "orchestrator/store/sqlite_db.h"
#include "tests/orchestrator/history/synthetic_sweep.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using slamsweep::testing::TempDir;

// The schema version 1 wrote, as it shipped.
constexpr const char* kVersion1Schema = R"sql(
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
PRAGMA application_id = 1397508179;
PRAGMA user_version = 1;
)sql";

struct OldNight {
  std::string label;
  std::string result_dir;
  int sweep_id = 1;
  std::string values_json;
};

void WriteVersion1History(const std::filesystem::path& file, const std::vector<OldNight>& nights) {
  SqliteDb db = SqliteDb::Open(file, true);
  db.Execute(kVersion1Schema);
  int id = 0;
  for (const OldNight& night : nights) {
    ++id;
    db.Execute(
        fmt::format("INSERT INTO nights VALUES({}, '{}', '{}', {}, 'nightly', '2026-11-{}T02:00:00Z', "
                    "'2026-11-{}T05:00:00Z', '')",
                    id, night.label, night.result_dir, night.sweep_id, 10 + id, 10 + id));
    db.Execute(
        fmt::format("INSERT INTO samples VALUES({}, 'icp-slam', 'intel', 'noisy', 'ape_trans', 'rmse', 'm', "
                    "'{}')",
                    id, night.values_json));
    db.Execute(
        fmt::format("INSERT INTO samples VALUES({}, 'icp-slam', 'intel', 'noisy', 'corners', 'value', "
                    "'count', '[40, 41]')",
                    id));
    db.Execute(fmt::format("INSERT INTO cells VALUES({}, 'icp-slam', 'intel', 'noisy', 5, 1)", id));
  }
}

std::int64_t UserVersion(const std::filesystem::path& file) {
  SqliteDb db = SqliteDb::Open(file, false);
  auto version = db.Prepare("PRAGMA user_version");
  version.Step();
  return version.Int64(0);
}

class HistoryMigrationTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // Result directories as the nights left them. Planned before the mode existed, on a corrected log: the
    // programs got the reference.
    testing::SyntheticSweep old;
    old.odometry = "";
    old.ground_truth = "corrected_poses";
    testing::WriteSyntheticSweep(dir_ / "old", old);
    old.seed = 2;
    testing::WriteSyntheticSweep(dir_ / "old2", old);
    // Planned with the mode: it says so.
    testing::SyntheticSweep planned;
    planned.odometry = "recorded";
    testing::WriteSyntheticSweep(dir_ / "planned", planned);
    // One cell in both modes in one night: its samples were pooled.
    testing::SyntheticSweep reference = planned;
    reference.odometry = "reference";
    reference.seed = 3;
    testing::WriteSyntheticSweep(dir_ / "both", planned);
    testing::WriteSyntheticSweep(dir_ / "both", reference);
    // A later sweep into a night's directory is not part of that night.
    testing::WriteSyntheticSweep(dir_ / "later", planned);
    testing::WriteSyntheticSweep(dir_ / "later", reference);

    WriteVersion1History(dir_ / "history.sqlite",
                         {{"old", (dir_ / "old").string(), 1, "[0.10, 0.11, 0.12, 0.13, 0.14]"},
                          {"old2", (dir_ / "old2").string(), 1, "[0.20, 0.21, 0.22, 0.23, 0.24]"},
                          {"planned", (dir_ / "planned").string(), 1, "[0.30, 0.31]"},
                          {"both", (dir_ / "both").string(), 2, "[0.40, 0.41]"},
                          {"later", (dir_ / "later").string(), 1, "[0.50, 0.51]"},
                          {"gone1", (dir_ / "gone1").string(), 1, "[0.10, 0.11, 0.12, 0.13, 0.14]"},
                          {"gone2", (dir_ / "gone2").string(), 1, "[0.20, 0.21, 0.22, 0.23, 0.24]"}});
  }

  Night LoadNight(const HistoryStore& store, const std::string& label) {
    return store.Load(store.FindByLabel(label)->id);
  }

  TempDir dir_;
};

TEST_F(HistoryMigrationTest, RowsKeepTheirValuesAndGetTheModeTheirResultsSay) {
  ASSERT_EQ(UserVersion(dir_ / "history.sqlite"), 1);
  const HistoryStore store = HistoryStore::Open(dir_ / "history.sqlite");
  EXPECT_EQ(UserVersion(dir_ / "history.sqlite"), 2);
  ASSERT_EQ(store.Nights().size(), 7u);

  const std::vector<std::pair<std::string, std::string>> expected = {
      {"old", "reference"},  {"old2", "reference"}, {"planned", "recorded"}, {"both", "mixed"},
      {"later", "recorded"}, {"gone1", "unknown"},  {"gone2", "unknown"}};
  for (const auto& [label, mode] : expected) {
    const Night night = LoadNight(store, label);
    ASSERT_EQ(night.series.size(), 2u) << label;
    for (const SampleSeries& s : night.series) EXPECT_EQ(s.odometry, mode) << label << " " << s.metric;
    ASSERT_EQ(night.cells.size(), 1u) << label;
    EXPECT_EQ(night.cells[0].odometry, mode) << label;
    EXPECT_EQ(night.cells[0].ok_runs, 5);
    EXPECT_EQ(night.cells[0].failed_runs, 1);
  }
  const Night old = LoadNight(store, "old");
  const SampleSeries* ape = FindSeries(old, {"icp-slam", "intel", "noisy", "reference", "ape_trans", "rmse", ""});
  ASSERT_NE(ape, nullptr);
  EXPECT_EQ(ape->values, (std::vector<double>{0.10, 0.11, 0.12, 0.13, 0.14}));
  EXPECT_EQ(ape->unit, "m");
  EXPECT_EQ(store.Series({"icp-slam", "intel", "noisy", "reference", "ape_trans", "rmse", ""}).size(), 2u);
  EXPECT_EQ(store.Series({"icp-slam", "intel", "noisy", "unknown", "ape_trans", "rmse", ""}).size(), 2u);
  EXPECT_EQ(store.Series({"icp-slam", "intel", "noisy", "recorded", "ape_trans", "rmse", ""}).size(), 2u);
  EXPECT_EQ(store.Series({"icp-slam", "intel", "noisy", "mixed", "ape_trans", "rmse", ""})[0].failed_runs, 1);

  // Opening again changes nothing; a new night can be recorded beside the migrated ones.
  HistoryStore reopened = HistoryStore::OpenExisting(dir_ / "history.sqlite");
  EXPECT_EQ(reopened.Nights().size(), 7u);
  EXPECT_EQ(LoadNight(reopened, "gone1").series[0].odometry, "unknown");
  testing::SyntheticSweep tonight;
  tonight.seed = 21;
  tonight.started_at = "2026-11-30T02:00:00Z";
  testing::WriteSyntheticSweep(dir_ / "tonight", tonight);
  EXPECT_TRUE(reopened.Record(ReadNight(dir_ / "tonight", "tonight")).inserted);
  EXPECT_EQ(reopened.Series({"icp-slam", "intel", "noisy", "recorded", "ape_trans", "rmse", ""}).size(), 3u);
}

TEST_F(HistoryMigrationTest, OnlyNightsOfAKnownModeAreCompared) {
  const HistoryStore store = HistoryStore::Open(dir_ / "history.sqlite");
  // Two migrated reference nights: every sample of the second above every one of the first (p = 2/252).
  const Comparison known = CompareNights(LoadNight(store, "old"), LoadNight(store, "old2"), {});
  ASSERT_EQ(known.findings.size(), 2u);
  EXPECT_EQ(known.findings[0].metric, "ape_trans");
  EXPECT_EQ(known.findings[0].verdict, Verdict::kRegression) << ComparisonToJson(known).dump(2);
  // The same samples under an unknown mode: not compared.
  const Comparison unknown = CompareNights(LoadNight(store, "gone1"), LoadNight(store, "gone2"), {});
  ASSERT_EQ(unknown.findings.size(), 2u);
  for (const Finding& f : unknown.findings) {
    EXPECT_EQ(f.verdict, Verdict::kNotComparable);
    EXPECT_EQ(f.odometry, "unknown");
    EXPECT_EQ(f.baseline_n, f.metric == "ape_trans" ? 5u : 2u);
  }
  EXPECT_NE(RenderComparisonJUnit(unknown).find("odometry mode unknown"), std::string::npos);
  // A mixed night compared with itself: not compared either.
  const Night both = LoadNight(store, "both");
  EXPECT_EQ(CompareNights(both, both, {}).Count(Verdict::kNotComparable), 2u);
  // A migrated recorded night and a reference one: two series, each on one side only.
  const Comparison across = CompareNights(LoadNight(store, "planned"), LoadNight(store, "old2"), {});
  EXPECT_EQ(across.findings.size(), 4u);
  EXPECT_EQ(across.Count(Verdict::kNotComparable), 4u);
}

}  // namespace
}  // namespace slamsweep::orchestrator
