// The odometry mode in the history's series key: nights on the robot's recorded odometry and nights handed the
// reference are separate series, and a regression check never compares one with the other.

#include <gtest/gtest.h>

#include "orchestrator/history/history_store.h"
#include "orchestrator/history/regression.h"
#include "orchestrator/history/series_odometry.h"
#include "tests/orchestrator/history/synthetic_sweep.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using slamsweep::testing::TempDir;

SeriesKey ApeKey(const std::string& odometry, const std::string& algorithm = "icp-slam") {
  return {algorithm, "intel", "noisy", odometry, "ape_trans", "rmse", ""};
}

std::vector<const Finding*> FindingsOf(const Comparison& comparison, const std::string& metric) {
  std::vector<const Finding*> found;
  for (const Finding& f : comparison.findings) {
    if (f.metric == metric) found.push_back(&f);
  }
  return found;
}

TEST(OdometryModeOfRunJsonTest, PlannedModeElseWhatTheSequenceSays) {
  using nlohmann::json;
  const json corrected = {{"format", "carmen"}, {"ground_truth", "corrected_poses"}};
  EXPECT_EQ(OdometryModeOfRunJson({{"group", {{"odometry", "recorded"}}}, {"sequence", corrected}}), "recorded");
  EXPECT_EQ(OdometryModeOfRunJson({{"group", {{"odometry", "reference"}}}, {"sequence", corrected}}), "reference");
  // Planned before the mode existed: a corrected log's programs got the logged (corrected) pose.
  EXPECT_EQ(OdometryModeOfRunJson({{"group", {{"noise", "clean"}}}, {"sequence", corrected}}), "reference");
  EXPECT_EQ(OdometryModeOfRunJson({{"sequence", corrected}}), "reference");
  json written = corrected;
  written["odometry"] = "recorded";
  EXPECT_EQ(OdometryModeOfRunJson({{"sequence", written}}), "recorded");
  // Other logs have only their recorded odometry.
  EXPECT_EQ(OdometryModeOfRunJson({{"sequence", {{"format", "rawlog"}, {"ground_truth", "none"}}}}), "recorded");
  EXPECT_EQ(OdometryModeOfRunJson({{"sequence", {{"format", "carmen"}, {"ground_truth", "relations_only"}}}}),
            "recorded");
  // Nothing to go by: unknown, never a guessed "recorded".
  EXPECT_EQ(OdometryModeOfRunJson({{"sequence", {{"name", "intel"}}}}), "unknown");
  EXPECT_EQ(OdometryModeOfRunJson(json::object()), "unknown");
  EXPECT_TRUE(IsComparableOdometryMode("recorded"));
  EXPECT_TRUE(IsComparableOdometryMode("reference"));
  EXPECT_FALSE(IsComparableOdometryMode("unknown"));
  EXPECT_FALSE(IsComparableOdometryMode("mixed"));
}

TEST(OdometrySeriesTest, TwoNightsOfOneCellInTwoModesAreTwoSeries) {
  TempDir dir;
  testing::SyntheticSweep recorded;
  recorded.odometry = "recorded";
  recorded.iterations = 6;
  testing::SyntheticSweep reference = recorded;
  reference.odometry = "reference";
  reference.seed = 2;
  reference.started_at = "2026-11-21T02:00:00Z";
  const std::vector<double> recorded_ape = testing::WriteSyntheticSweep(dir / "monday", recorded);
  const std::vector<double> reference_ape = testing::WriteSyntheticSweep(dir / "tuesday", reference);

  HistoryStore store = HistoryStore::Open(dir / "history.sqlite");
  store.Record(ReadNight(dir / "monday", "monday"));
  store.Record(ReadNight(dir / "tuesday", "tuesday"));
  // ape_trans mean and rmse, corners value: three metrics x two modes.
  const std::vector<SeriesKey> keys = store.SeriesKeys();
  ASSERT_EQ(keys.size(), 6u);
  std::size_t rmse_keys = 0;
  for (const SeriesKey& key : keys) rmse_keys += key.metric == "ape_trans" && key.statistic == "rmse";
  EXPECT_EQ(rmse_keys, 2u);

  const auto recorded_points = store.Series(ApeKey("recorded"));
  ASSERT_EQ(recorded_points.size(), 1u);
  EXPECT_EQ(recorded_points[0].night.label, "monday");
  EXPECT_EQ(recorded_points[0].values, recorded_ape);
  const auto reference_points = store.Series(ApeKey("reference"));
  ASSERT_EQ(reference_points.size(), 1u);
  EXPECT_EQ(reference_points[0].night.label, "tuesday");
  EXPECT_EQ(reference_points[0].values, reference_ape);

  // The cells keep the mode too.
  const Night loaded = store.Load(store.FindByLabel("tuesday")->id);
  ASSERT_EQ(loaded.cells.size(), 1u);
  EXPECT_EQ(loaded.cells[0].odometry, "reference");
  EXPECT_EQ(loaded.cells[0].ok_runs, 6);
}

TEST(OdometrySeriesTest, OneNightWithBothModesKeepsTheirSamplesApart) {
  TempDir dir;
  testing::SyntheticSweep recorded;
  recorded.odometry = "recorded";
  recorded.iterations = 4;
  recorded.failed_iterations = {3};
  testing::SyntheticSweep reference = recorded;
  reference.odometry = "reference";
  reference.seed = 5;
  reference.iterations = 5;
  reference.failed_iterations = {};
  const std::vector<double> recorded_ape = testing::WriteSyntheticSweep(dir / "night", recorded);
  const std::vector<double> reference_ape = testing::WriteSyntheticSweep(dir / "night", reference);

  const Night night = ReadNight(dir / "night", "");
  ASSERT_EQ(night.cells.size(), 2u);
  EXPECT_EQ(night.cells[0].odometry, "recorded");
  EXPECT_EQ(night.cells[0].ok_runs, 3);
  EXPECT_EQ(night.cells[0].failed_runs, 1);
  EXPECT_EQ(night.cells[1].odometry, "reference");
  EXPECT_EQ(night.cells[1].ok_runs, 5);
  EXPECT_EQ(night.cells[1].failed_runs, 0);
  ASSERT_NE(FindSeries(night, ApeKey("recorded")), nullptr);
  EXPECT_EQ(FindSeries(night, ApeKey("recorded"))->values, recorded_ape);
  ASSERT_NE(FindSeries(night, ApeKey("reference")), nullptr);
  EXPECT_EQ(FindSeries(night, ApeKey("reference"))->values, reference_ape);

  HistoryStore store = HistoryStore::Open(dir / "history.sqlite");
  const auto id = store.Record(night).id;
  const Night loaded = store.Load(id);
  EXPECT_EQ(FindSeries(loaded, ApeKey("reference"))->values, reference_ape);
  EXPECT_EQ(store.Series(ApeKey("recorded"))[0].failed_runs, 1);
  EXPECT_EQ(store.Series(ApeKey("reference"))[0].failed_runs, 0);
}

TEST(OdometrySeriesTest, NoRegressionBetweenModes) {
  TempDir dir;
  testing::SyntheticSweep baseline;
  baseline.odometry = "recorded";
  testing::SyntheticSweep current = baseline;
  current.odometry = "reference";
  current.odometry_sigma = 2.0 * baseline.odometry_sigma;  // a regression, were the two nights one series
  current.seed = 7;
  testing::WriteSyntheticSweep(dir / "before", baseline);
  testing::WriteSyntheticSweep(dir / "after", current);
  const Night before = ReadNight(dir / "before", "before");
  const Night after = ReadNight(dir / "after", "after");

  const Comparison comparison = CompareNights(before, after, {});
  EXPECT_FALSE(comparison.HasRegression()) << ComparisonToJson(comparison).dump(2);
  EXPECT_EQ(comparison.Count(Verdict::kImprovement), 0u);
  const std::vector<const Finding*> ape = FindingsOf(comparison, "ape_trans");
  ASSERT_EQ(ape.size(), 2u);  // one per mode, ordered recorded, reference
  EXPECT_EQ(ape[0]->odometry, "recorded");
  EXPECT_EQ(ape[0]->baseline_n, 10u);
  EXPECT_EQ(ape[0]->current_n, 0u);
  EXPECT_EQ(ape[1]->odometry, "reference");
  EXPECT_EQ(ape[1]->baseline_n, 0u);
  EXPECT_EQ(ape[1]->current_n, 10u);
  for (const Finding* f : ape) EXPECT_EQ(f->verdict, Verdict::kNotComparable);

  const nlohmann::json json = ComparisonToJson(comparison);
  EXPECT_EQ(json["findings"][0]["odometry"], "recorded");
  const std::string xml = RenderComparisonJUnit(comparison);
  EXPECT_NE(xml.find("classname=\"icp-slam.intel.noisy.recorded\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("classname=\"icp-slam.intel.noisy.reference\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("failures=\"0\""), std::string::npos);
}

TEST(OdometrySeriesTest, RegressionWithinOneModeIsStillFound) {
  TempDir dir;
  // Both nights ran both modes; only the runs on the recorded odometry got worse.
  testing::SyntheticSweep recorded;
  recorded.odometry = "recorded";
  testing::SyntheticSweep reference = recorded;
  reference.odometry = "reference";
  reference.seed = 11;
  testing::WriteSyntheticSweep(dir / "before", recorded);
  testing::WriteSyntheticSweep(dir / "before", reference);
  testing::SyntheticSweep worse = recorded;
  worse.odometry_sigma = 2.0 * recorded.odometry_sigma;
  worse.seed = 7;
  testing::SyntheticSweep same = reference;
  same.seed = 99;
  testing::WriteSyntheticSweep(dir / "after", worse);
  testing::WriteSyntheticSweep(dir / "after", same);

  const Comparison comparison =
      CompareNights(ReadNight(dir / "before", "before"), ReadNight(dir / "after", "after"), {});
  EXPECT_EQ(comparison.Count(Verdict::kRegression), 1u) << ComparisonToJson(comparison).dump(2);
  const std::vector<const Finding*> ape = FindingsOf(comparison, "ape_trans");
  ASSERT_EQ(ape.size(), 2u);
  EXPECT_EQ(ape[0]->odometry, "recorded");
  EXPECT_EQ(ape[0]->verdict, Verdict::kRegression);
  EXPECT_EQ(ape[0]->baseline_n, 10u);
  EXPECT_EQ(ape[0]->current_n, 10u);
  EXPECT_EQ(ape[1]->odometry, "reference");
  EXPECT_EQ(ape[1]->verdict, Verdict::kUnchanged);
  EXPECT_EQ(ape[1]->baseline_n, 10u);
}

TEST(OdometrySeriesTest, ParameterSettingsAreSeriesOfTheirOwn) {
  TempDir dir;
  testing::SyntheticSweep low;
  low.parameters = {{"particles", 30}};
  testing::SyntheticSweep high = low;
  high.parameters = {{"particles", 60}};
  high.seed = 3;
  testing::WriteSyntheticSweep(dir / "before", low);
  testing::WriteSyntheticSweep(dir / "before", high);
  testing::SyntheticSweep high_worse = high;
  high_worse.odometry_sigma *= 2.0;
  high_worse.seed = 8;
  testing::SyntheticSweep low_again = low;
  low_again.seed = 9;
  testing::WriteSyntheticSweep(dir / "after", low_again);
  testing::WriteSyntheticSweep(dir / "after", high_worse);

  const Night before = ReadNight(dir / "before", "before");
  EXPECT_NE(FindSeries(before, ApeKey("recorded", "icp-slam [particles=30]")), nullptr);
  EXPECT_NE(FindSeries(before, ApeKey("recorded", "icp-slam [particles=60]")), nullptr);
  EXPECT_EQ(FindSeries(before, ApeKey("recorded", "icp-slam")), nullptr);
  const Comparison comparison = CompareNights(before, ReadNight(dir / "after", "after"), {});
  ASSERT_EQ(comparison.Count(Verdict::kRegression), 1u) << ComparisonToJson(comparison).dump(2);
  for (const Finding& f : comparison.findings) {
    if (f.verdict == Verdict::kRegression) {
      EXPECT_EQ(f.algorithm, "icp-slam [particles=60]");
    }
  }
}

}  // namespace
}  // namespace slamsweep::orchestrator
