// The significance of a table's "best": one-sided tests against the runner-up and the odometry baseline,
// Holm-corrected over the report. Expected p-values are hand computations of the exact distributions
// (Wilcoxon: 1 / 2^n for n pairs all in one direction; Mann-Whitney: 1 / C(n_x + n_y, n_x) for separated
// samples).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "report/model/load_runs.h"
#include "report/model/named_study.h"
#include "report/model/significance.h"
#include "tests/report/fixture_sweep.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

using slamsweep::testing::TempDir;
using testing::FixtureRun;
using ::testing::HasSubstr;
using testing::MakeRun;

/// `iterations` runs each of "good", "fair" and the odometry baseline on "floor"; good is lower than fair in
/// every iteration by a different amount (no tied differences). The fixture seeds iteration i with 1000 + i
/// for every algorithm, so rows pair by iteration.
std::vector<FixtureRun> Runs(int iterations, int fair_iterations = -1) {
  if (fair_iterations < 0) fair_iterations = iterations;
  std::vector<FixtureRun> runs;
  for (int i = 0; i < iterations; ++i) {
    FixtureRun good = MakeRun("good", "floor", i);
    good.ape_rmse_m = 0.10 + 0.001 * i;
    runs.push_back(good);
    FixtureRun odometry = MakeRun("odometry", "floor", i);
    odometry.adapter = "odometry";
    odometry.ape_rmse_m = 2.0 + 0.1 * i * i;
    runs.push_back(odometry);
  }
  for (int i = 0; i < fair_iterations; ++i) {
    FixtureRun fair = MakeRun("fair", "floor", i);
    fair.ape_rmse_m = 0.10 + 0.001 * i + 0.01 * (i + 1);
    runs.push_back(fair);
  }
  return runs;
}

std::vector<TableSignificance> Significance(const std::vector<FixtureRun>& runs) {
  TempDir dir;
  testing::WriteFixtureSweep(dir.path(), runs);
  return BuildSignificance(BuildSweepModel(LoadRuns(dir.path()), LoadSweepModelOptions(dir.path())));
}

TEST(SignificanceTest, FivePairedRunsCannotReachTheLevelAfterHolmAndSayHowManyAreNeeded) {
  const std::vector<TableSignificance> tables = Significance(Runs(5));
  ASSERT_EQ(tables.size(), 1u);
  const TableSignificance& t = tables[0];
  EXPECT_EQ(t.metric_title, "ATE translation RMSE");
  ASSERT_TRUE(t.vs_runner_up);
  EXPECT_EQ(t.vs_runner_up->other, "fair");
  EXPECT_TRUE(t.vs_runner_up->paired);
  EXPECT_EQ(t.vs_runner_up->test, "Wilcoxon signed-rank");
  EXPECT_DOUBLE_EQ(t.vs_runner_up->p_value, 1.0 / 32.0);
  EXPECT_DOUBLE_EQ(t.vs_runner_up->cliffs_delta, -1.0);  // every good value below every fair value
  ASSERT_TRUE(t.vs_baseline);
  EXPECT_EQ(t.vs_baseline->other, "odometry");
  EXPECT_DOUBLE_EQ(t.vs_baseline->p_value, 1.0 / 32.0);
  EXPECT_DOUBLE_EQ(t.vs_baseline->cliffs_delta, -1.0);
  // Two tests: Holm multiplies the smaller p by 2, and the larger (equal) one stays at that value.
  EXPECT_DOUBLE_EQ(t.vs_runner_up->p_holm, 1.0 / 16.0);
  EXPECT_DOUBLE_EQ(t.vs_baseline->p_holm, 1.0 / 16.0);
  // 1/32 > 0.05 / 2: no outcome of 5 pairs could be significant; 6 pairs reach 1/64 <= 0.025.
  EXPECT_EQ(t.iterations_needed, 6u);
  EXPECT_THAT(t.verdict, HasSubstr("not significantly different from fair"));
  EXPECT_THAT(t.verdict, HasSubstr("too few runs"));
  EXPECT_THAT(t.verdict, HasSubstr("6 iterations per row are needed"));
}

TEST(SignificanceTest, TheRankingListsCandidatesByMeanAndShowsTheOthersBeside) {
  std::vector<FixtureRun> runs = Runs(5);
  FixtureRun flaky = MakeRun("flaky", "floor", 0);
  flaky.ape_rmse_m = 0.01;  // lowest of all, but one of its two runs failed
  runs.push_back(flaky);
  FixtureRun failed = MakeRun("flaky", "floor", 1);
  failed.ok = false;
  runs.push_back(failed);
  const TableSignificance t = Significance(runs).at(0);
  ASSERT_EQ(t.entries.size(), 4u);
  auto name = [&](const RankedEntry& entry) {
    return std::vector<std::string>{"fair", "flaky", "good", "odometry"}[entry.row];
  };
  EXPECT_EQ(name(t.entries[0]), "good");
  EXPECT_EQ(t.entries[0].rank, 1u);
  EXPECT_EQ(name(t.entries[1]), "fair");
  EXPECT_EQ(t.entries[1].rank, 2u);
  // good: 0.100 .. 0.104, mean 0.102, s = 0.0015811; t(0.975, 4) = 2.7764451 (scipy.stats.t.ppf).
  ASSERT_TRUE(t.entries[0].interval);
  EXPECT_NEAR(t.entries[0].interval->low, 0.102 - 2.7764451052 * 0.00158113883 / std::sqrt(5.0), 1e-9);
  EXPECT_EQ(name(t.entries[2]), "flaky");
  EXPECT_FALSE(t.entries[2].rank);
  EXPECT_EQ(t.entries[2].unranked_because, "1 of 2 runs ok");
  EXPECT_EQ(name(t.entries[3]), "odometry");
  EXPECT_FALSE(t.entries[3].rank);
  EXPECT_EQ(t.entries[3].unranked_because, "odometry baseline (the line to beat)");
  EXPECT_EQ(t.entries[3].n_ok, 5u);
}

TEST(SignificanceTest, EightPairedRunsAllInOneDirectionAreSignificant) {
  const std::vector<TableSignificance> tables = Significance(Runs(8));
  const TableSignificance& t = tables.at(0);
  ASSERT_TRUE(t.vs_runner_up);
  EXPECT_DOUBLE_EQ(t.vs_runner_up->p_value, 1.0 / 256.0);
  EXPECT_DOUBLE_EQ(t.vs_runner_up->p_holm, 2.0 / 256.0);
  EXPECT_EQ(t.iterations_needed, 0u);
  EXPECT_THAT(t.verdict, HasSubstr("best, significantly: lower than fair"));
}

TEST(SignificanceTest, UnpairedRowsUseMannWhitney) {
  // fair ran 4 iterations, good 5: the seeds differ in number, so the rows do not pair. good's five values
  // 0.100..0.104 all lie below fair's 0.110..0.143: separated, p = 1 / C(9, 5) = 1/126.
  const std::vector<TableSignificance> tables = Significance(Runs(5, 4));
  const TableSignificance& t = tables.at(0);
  ASSERT_TRUE(t.vs_runner_up);
  EXPECT_FALSE(t.vs_runner_up->paired);
  EXPECT_EQ(t.vs_runner_up->test, "Mann-Whitney U");
  EXPECT_NEAR(t.vs_runner_up->p_value, 1.0 / 126.0, 1e-15);
  EXPECT_DOUBLE_EQ(t.vs_runner_up->cliffs_delta, -1.0);
}

TEST(SignificanceTest, IdenticalRunsAreTiesNotEvidence) {
  std::vector<FixtureRun> runs;
  for (int i = 0; i < 6; ++i) {
    for (const char* name : {"alpha", "beta"}) {
      FixtureRun run = MakeRun(name, "floor", i);
      run.ape_rmse_m = 0.25;  // a deterministic program without noise: the same value every iteration
      runs.push_back(run);
    }
  }
  const TableSignificance t = Significance(runs).at(0);
  ASSERT_TRUE(t.vs_runner_up);
  EXPECT_TRUE(t.vs_runner_up->identical);
  EXPECT_THAT(t.verdict, HasSubstr("tied with"));
  EXPECT_THAT(t.verdict, HasSubstr("identical runs are ties, not evidence"));
}

TEST(SignificanceTest, ATableWithoutReferenceHasNoHeadline) {
  std::vector<FixtureRun> runs;
  for (int i = 0; i < 3; ++i) {
    FixtureRun run = MakeRun("alpha", "hall", i);
    run.with_reference = false;
    run.corners = 10.0 + i;
    runs.push_back(run);
  }
  const TableSignificance t = Significance(runs).at(0);
  EXPECT_EQ(t.metric_title, "");
  EXPECT_FALSE(t.vs_runner_up);
  EXPECT_THAT(t.verdict, HasSubstr("only ground-truth-free metrics"));
}

TEST(SignificanceTest, IterationsNeededFollowTheSmallestReachablePValue) {
  EXPECT_EQ(IterationsNeeded(0.05, true), 5u);    // 1/32 <= 0.05, 1/16 is not
  EXPECT_EQ(IterationsNeeded(0.025, true), 6u);   // 1/64
  EXPECT_EQ(IterationsNeeded(0.04, false), 4u);   // 1/C(8,4) = 1/70; 1/C(6,3) = 1/20 is not
  EXPECT_EQ(IterationsNeeded(0.001, false), 7u);  // 1/C(14,7) = 1/3432; 1/C(12,6) = 1/924 is not
}

}  // namespace
}  // namespace slamsweep::report
