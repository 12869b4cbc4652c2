#include "orchestrator/history/regression.h"

#include <gtest/gtest.h>

#include "evaluator/core/input_error.h"
#include "tests/orchestrator/history/synthetic_sweep.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using slamsweep::testing::TempDir;

const Finding* Find(const Comparison& comparison, const std::string& metric) {
  for (const Finding& f : comparison.findings) {
    if (f.metric == metric) return &f;
  }
  return nullptr;
}

struct TwoNights {
  Night baseline;
  Night current;
};

TwoNights MakeNights(const TempDir& dir, const testing::SyntheticSweep& before, const testing::SyntheticSweep& after) {
  testing::WriteSyntheticSweep(dir / "before", before);
  testing::WriteSyntheticSweep(dir / "after", after);
  return {ReadNight(dir / "before", "before"), ReadNight(dir / "after", "after")};
}

TEST(RegressionTest, DoubledOdometryNoiseIsARegression) {
  TempDir dir;
  testing::SyntheticSweep before;
  testing::SyntheticSweep after = before;
  after.odometry_sigma = 2.0 * before.odometry_sigma;  // the injected regression
  after.seed = 7;
  const TwoNights nights = MakeNights(dir, before, after);
  const Comparison comparison = CompareNights(nights.baseline, nights.current, {});
  const Finding* ape = Find(comparison, "ape_trans");
  ASSERT_NE(ape, nullptr);
  EXPECT_EQ(ape->statistic, "rmse");  // not mean: trajectory metrics are compared on rmse
  EXPECT_EQ(ape->verdict, Verdict::kRegression);
  EXPECT_LT(ape->test.p_value, 0.05);
  EXPECT_GT(ape->cliffs_delta, 0.2);
  EXPECT_GT(ape->current_median, ape->baseline_median);
  EXPECT_TRUE(comparison.HasRegression());
  // The corner count does not depend on the odometry in this model: not flagged.
  const Finding* corners = Find(comparison, "corners");
  ASSERT_NE(corners, nullptr);
  EXPECT_EQ(corners->statistic, "value");
  EXPECT_NE(corners->verdict, Verdict::kRegression);
  EXPECT_EQ(comparison.findings.size(), 2u);

  // The other way round it is an improvement, not a regression.
  const Comparison reverse = CompareNights(nights.current, nights.baseline, {});
  EXPECT_EQ(Find(reverse, "ape_trans")->verdict, Verdict::kImprovement);
  EXPECT_FALSE(reverse.HasRegression());
}

Night NightWith(const std::string& label, const std::string& metric, std::vector<double> values) {
  Night night;
  night.label = label;
  SampleSeries series;
  series.algorithm = "gmapping";
  series.sequence = "intel";
  series.noise = "none";
  series.odometry = "recorded";
  series.metric = metric;
  series.statistic = "value";
  series.unit = "ratio";
  series.values = std::move(values);
  night.series.push_back(std::move(series));
  return night;
}

TEST(RegressionTest, AMapScoreThatGrowsIsAnImprovementAndOneThatFallsARegression) {
  const std::vector<double> low = {0.50, 0.51, 0.52, 0.53, 0.54, 0.55, 0.56, 0.57};
  const std::vector<double> high = {0.80, 0.81, 0.82, 0.83, 0.84, 0.85, 0.86, 0.87};
  for (const char* score : {"map_f1", "map_accuracy", "map_completeness", "map_iou_occupied", "map_iou_free"}) {
    const Comparison better = CompareNights(NightWith("before", score, low), NightWith("after", score, high), {});
    ASSERT_EQ(better.findings.size(), 1u);
    EXPECT_EQ(better.findings[0].verdict, Verdict::kImprovement) << score;
    const Comparison worse = CompareNights(NightWith("before", score, high), NightWith("after", score, low), {});
    EXPECT_EQ(worse.findings[0].verdict, Verdict::kRegression) << score;
  }
  // An error that grows the same way stays a regression.
  const Comparison chamfer =
      CompareNights(NightWith("before", "map_chamfer", low), NightWith("after", "map_chamfer", high), {});
  EXPECT_EQ(chamfer.findings[0].verdict, Verdict::kRegression);
}

TEST(RegressionTest, ReRunOfTheSameSettingIsNotFlagged) {
  TempDir dir;
  testing::SyntheticSweep before;
  testing::SyntheticSweep after = before;
  after.seed = 99;  // same distribution, other samples
  const TwoNights nights = MakeNights(dir, before, after);
  const Comparison comparison = CompareNights(nights.baseline, nights.current, {});
  EXPECT_FALSE(comparison.HasRegression()) << ComparisonToJson(comparison).dump(2);
  EXPECT_EQ(comparison.Count(Verdict::kImprovement), 0u);
  // Identical nights: U is half of n1 n2 and delta 0.
  const Comparison same = CompareNights(nights.baseline, nights.baseline, {});
  EXPECT_DOUBLE_EQ(Find(same, "ape_trans")->cliffs_delta, 0.0);
  EXPECT_DOUBLE_EQ(Find(same, "ape_trans")->test.p_value, 1.0);
}

TEST(RegressionTest, MinEffectAndAlphaGateTheVerdict) {
  TempDir dir;
  testing::SyntheticSweep before;
  testing::SyntheticSweep after = before;
  after.odometry_sigma = 2.0 * before.odometry_sigma;
  after.seed = 7;
  const TwoNights nights = MakeNights(dir, before, after);
  // min_effect 1 needs complete separation (every current sample worse than every baseline sample).
  const double delta = Find(CompareNights(nights.baseline, nights.current, {}), "ape_trans")->cliffs_delta;
  EXPECT_EQ(Find(CompareNights(nights.baseline, nights.current, {0.05, 1.0}), "ape_trans")->verdict,
            delta >= 1.0 ? Verdict::kRegression : Verdict::kUnchanged);
  // The smallest two-sided p with 10 + 10 samples is 2 / C(20, 10) ~ 1.1e-5: alpha 1e-6 can never be reached.
  EXPECT_EQ(Find(CompareNights(nights.baseline, nights.current, {1e-6, 0.2}), "ape_trans")->verdict,
            Verdict::kUnchanged);
  EXPECT_THROW(CompareNights(nights.baseline, nights.current, {0.0, 0.2}), evaluator::InputError);
  EXPECT_THROW(CompareNights(nights.baseline, nights.current, {0.05, 1.5}), evaluator::InputError);
}

TEST(RegressionTest, AllRunsFailedIsNotComparable) {
  TempDir dir;
  testing::SyntheticSweep before;
  testing::SyntheticSweep after = before;
  after.failed_iterations = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  const TwoNights nights = MakeNights(dir, before, after);
  const Comparison comparison = CompareNights(nights.baseline, nights.current, {});
  ASSERT_EQ(comparison.findings.size(), 2u);
  for (const Finding& f : comparison.findings) {
    EXPECT_EQ(f.verdict, Verdict::kNotComparable);
    EXPECT_EQ(f.current_n, 0u);
  }
  const nlohmann::json json = ComparisonToJson(comparison);
  EXPECT_TRUE(json["findings"][0]["current_median"].is_null());
  EXPECT_EQ(json["counts"]["not_comparable"], 2);
}

TEST(RegressionTest, JUnitHasOneFailurePerRegression) {
  TempDir dir;
  testing::SyntheticSweep before;
  testing::SyntheticSweep after = before;
  after.odometry_sigma = 2.0 * before.odometry_sigma;
  after.seed = 7;
  after.algorithm = "icp<&>";  // escaped in XML
  const TwoNights nights = MakeNights(dir, before, after);
  // Different algorithm names: every series is new or gone -> skipped, no failure.
  const std::string skipped = RenderComparisonJUnit(CompareNights(nights.baseline, nights.current, {}));
  EXPECT_NE(skipped.find("failures=\"0\""), std::string::npos) << skipped;
  EXPECT_NE(skipped.find("<skipped"), std::string::npos);
  EXPECT_NE(skipped.find("icp&lt;&amp;&gt;"), std::string::npos);
  EXPECT_EQ(skipped.find("icp<&>"), std::string::npos);

  before.algorithm = after.algorithm;
  TempDir dir2;
  const TwoNights same_names = MakeNights(dir2, before, after);
  const std::string xml = RenderComparisonJUnit(CompareNights(same_names.baseline, same_names.current, {}));
  EXPECT_NE(xml.find("failures=\"1\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("<failure type=\"regression\""), std::string::npos);
  EXPECT_NE(xml.find("name=\"ape_trans.rmse\""), std::string::npos);
}

}  // namespace
}  // namespace slamsweep::orchestrator
