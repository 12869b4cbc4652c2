#include "orchestrator/history/history_store.h"

#include <gtest/gtest.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/history/night.h"
#include "tests/orchestrator/history/synthetic_sweep.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using slamsweep::testing::TempDir;

TEST(ReadNightTest, SamplesPerSeriesAndFailedRuns) {
  TempDir dir;
  testing::SyntheticSweep sweep;
  sweep.iterations = 5;
  sweep.failed_iterations = {2};
  const std::vector<double> ape = testing::WriteSyntheticSweep(dir / "night", sweep);
  const Night night = ReadNight(dir / "night", "");
  EXPECT_EQ(night.label, "2026-11-20T02:00:00Z");  // the sweep's start time
  EXPECT_EQ(night.sweep_name, "nightly");
  EXPECT_TRUE(night.result_dir.is_absolute());
  ASSERT_EQ(night.cells.size(), 1u);
  EXPECT_EQ(night.cells[0].ok_runs, 4);
  EXPECT_EQ(night.cells[0].failed_runs, 1);
  const SampleSeries* rmse = FindSeries(night, {"icp-slam", "intel", "noisy", "recorded", "ape_trans", "rmse", ""});
  ASSERT_NE(rmse, nullptr);
  EXPECT_EQ(rmse->values, ape);  // ok runs only, iteration order
  EXPECT_EQ(rmse->unit, "m");
  ASSERT_NE(FindSeries(night, {"icp-slam", "intel", "noisy", "recorded", "corners", "value", ""}), nullptr);
  EXPECT_EQ(FindSeries(night, {"icp-slam", "intel", "clean", "recorded", "corners", "value", ""}), nullptr);
  EXPECT_EQ(ReadNight(dir / "night", "my-label").label, "my-label");
}

TEST(ReadNightTest, MissingResultsDatabaseIsInputError) {
  TempDir dir;
  try {
    ReadNight(dir / "nothing", "");
    FAIL() << "expected InputError";
  } catch (const evaluator::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("results.sqlite"), std::string::npos) << error.what();
  }
}

TEST(HistoryStoreTest, RecordIsIdempotentAndRoundTrips) {
  TempDir dir;
  testing::SyntheticSweep sweep;
  testing::WriteSyntheticSweep(dir / "night1", sweep);
  sweep.seed = 2;
  sweep.started_at = "2026-11-21T02:00:00Z";
  testing::WriteSyntheticSweep(dir / "night2", sweep);

  HistoryStore store = HistoryStore::Open(dir / "var/history.sqlite");
  const Night first = ReadNight(dir / "night1", "");
  const auto recorded = store.Record(first);
  EXPECT_TRUE(recorded.inserted);
  const auto again = store.Record(ReadNight(dir / "night1", "another label"));
  EXPECT_FALSE(again.inserted);
  EXPECT_EQ(again.id, recorded.id);
  EXPECT_EQ(store.Nights().size(), 1u);

  // Reopened from disk: the same night, samples intact.
  HistoryStore reopened = HistoryStore::OpenExisting(dir / "var/history.sqlite");
  const Night loaded = reopened.Load(recorded.id);
  EXPECT_EQ(loaded.label, first.label);
  EXPECT_EQ(loaded.result_dir, first.result_dir);
  ASSERT_EQ(loaded.series.size(), first.series.size());
  for (std::size_t i = 0; i < first.series.size(); ++i) {
    EXPECT_EQ(loaded.series[i].metric, first.series[i].metric);
    EXPECT_EQ(loaded.series[i].values, first.series[i].values);
  }
  EXPECT_EQ(loaded.cells.size(), first.cells.size());

  EXPECT_TRUE(reopened.Record(ReadNight(dir / "night2", "")).inserted);
  const auto nights = reopened.Nights();
  ASSERT_EQ(nights.size(), 2u);
  EXPECT_EQ(nights[1].label, "2026-11-21T02:00:00Z");
  EXPECT_TRUE(reopened.FindByLabel("2026-11-20T02:00:00Z").has_value());
  EXPECT_FALSE(reopened.FindByLabel("nope").has_value());
  // Series across nights: ape_trans mean and rmse, corners value (sorted by metric, then statistic).
  const std::vector<SeriesKey> keys = reopened.SeriesKeys();
  ASSERT_EQ(keys.size(), 3u);
  EXPECT_EQ(keys[0].statistic, "mean");
  EXPECT_EQ(keys[1].statistic, "rmse");
  EXPECT_EQ(keys[2].metric, "corners");
  EXPECT_EQ(keys[2].unit, "count");
  // --previous: for a recorded night the one recorded before it; for an unrecorded one the last recorded.
  EXPECT_EQ(PreviousNight(reopened, ReadNight(dir / "night2", ""))->label, "2026-11-20T02:00:00Z");
  EXPECT_FALSE(PreviousNight(reopened, first).has_value());
  testing::SyntheticSweep third = sweep;
  third.seed = 3;
  testing::WriteSyntheticSweep(dir / "night3", third);
  EXPECT_EQ(PreviousNight(reopened, ReadNight(dir / "night3", ""))->label, "2026-11-21T02:00:00Z");
  // A night on the reference odometry in between is passed over by the next recorded-odometry night, and
  // found by the next reference-odometry one.
  testing::SyntheticSweep other_mode = sweep;
  other_mode.seed = 4;
  other_mode.odometry = "reference";
  other_mode.ground_truth = "corrected_poses";
  other_mode.started_at = "2026-11-22T02:00:00Z";
  testing::WriteSyntheticSweep(dir / "night4", other_mode);
  ASSERT_TRUE(reopened.Record(ReadNight(dir / "night4", "")).inserted);
  EXPECT_EQ(PreviousNight(reopened, ReadNight(dir / "night3", ""))->label, "2026-11-21T02:00:00Z");
  testing::SyntheticSweep fifth = other_mode;
  fifth.seed = 5;
  testing::WriteSyntheticSweep(dir / "night5", fifth);
  EXPECT_EQ(PreviousNight(reopened, ReadNight(dir / "night5", ""))->label, "2026-11-22T02:00:00Z");
  const auto series = reopened.Series({"icp-slam", "intel", "noisy", "recorded", "ape_trans", "rmse", ""});
  ASSERT_EQ(series.size(), 2u);
  EXPECT_EQ(series[0].values.size(), 10u);
  EXPECT_EQ(series[1].night.label, "2026-11-21T02:00:00Z");
}

TEST(HistoryStoreTest, LabelClashAndWrongFilesAreInputErrors) {
  TempDir dir;
  testing::SyntheticSweep sweep;
  testing::WriteSyntheticSweep(dir / "night1", sweep);
  testing::WriteSyntheticSweep(dir / "night2", sweep);  // same start time -> same default label
  HistoryStore store = HistoryStore::Open(dir / "history.sqlite");
  store.Record(ReadNight(dir / "night1", ""));
  EXPECT_THROW(store.Record(ReadNight(dir / "night2", "")), evaluator::InputError);
  EXPECT_TRUE(store.Record(ReadNight(dir / "night2", "second")).inserted);

  // A results database is not a history database.
  EXPECT_THROW(HistoryStore::Open(dir / "night1/results.sqlite"), evaluator::InputError);
  EXPECT_THROW(HistoryStore::OpenExisting(dir / "missing.sqlite"), evaluator::InputError);
  slamsweep::testing::WriteFile(dir / "garbage.sqlite", std::string(4096, 'x'));
  EXPECT_THROW(HistoryStore::Open(dir / "garbage.sqlite"), evaluator::InputError);
}

}  // namespace
}  // namespace slamsweep::orchestrator
