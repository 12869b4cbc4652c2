// The verdict across data sets on a sweep shaped like the paper's: which tables count, which rows are
// contestants, their mean ranks, Friedman with Iman-Davenport and Nemenyi's critical difference. Expected values
// are worked out by hand in fixture_sweep.cc (PaperLikeFixtureRuns) and below; Demšar's table gives q_0.05.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "report/model/across_data_sets.h"
#include "report/model/load_runs.h"
#include "report/model/named_study.h"
#include "tests/report/fixture_sweep.h"
#include "tests/support/shared_data.h"

namespace slamsweep::report {
namespace {

using slamsweep::testing::TempDir;
using testing::FixtureRun;
using ::testing::HasSubstr;

std::vector<DataSetVerdict> Verdicts(const std::vector<FixtureRun>& runs) {
  TempDir dir;
  testing::WriteFixtureSweep(dir.path(), runs);
  const SweepModel model = BuildSweepModel(LoadRuns(dir.path()), LoadSweepModelOptions(dir.path()));
  return BuildAcrossDataSets(model, BuildSignificance(model));
}

const DataSetChoice& Choice(const DataSetVerdict& v, const std::string& sequence) {
  for (const DataSetChoice& c : v.data_sets) {
    if (c.table_key.rfind(sequence + "/", 0) == 0) return c;
  }
  throw std::runtime_error("no table " + sequence);
}

TEST(AcrossDataSetsTest, PaperLikeSweepRanksFiveContestantsOverThreeIndependentDataSets) {
  const std::vector<DataSetVerdict> verdicts = Verdicts(testing::PaperLikeFixtureRuns());
  ASSERT_EQ(verdicts.size(), 1u);  // one noise setting, one odometry mode
  const DataSetVerdict& v = verdicts[0];
  ASSERT_EQ(v.data_sets.size(), 5u);
  EXPECT_TRUE(Choice(v, "intel-full-rate").used);
  EXPECT_TRUE(Choice(v, "fr079").used);
  EXPECT_TRUE(Choice(v, "simulated-floor").used);
  EXPECT_FALSE(Choice(v, "intel-dense").used);
  EXPECT_THAT(Choice(v, "intel-dense").why, HasSubstr("same physical run"));
  EXPECT_THAT(Choice(v, "intel-dense").why, HasSubstr("7.35 scans/s, against 1.00 scans/s"));
  EXPECT_FALSE(Choice(v, "mit-csail").used);
  EXPECT_THAT(Choice(v, "mit-csail").why, HasSubstr("corrected log"));
  EXPECT_THAT(Choice(v, "fr079").why, HasSubstr("relations"));
  EXPECT_THAT(Choice(v, "simulated-floor").why, HasSubstr("exact ground truth"));
  ASSERT_EQ(v.used.size(), 3u);

  // rbpf-slam failed a run on fr079; the odometry baseline is never a contestant.
  ASSERT_EQ(v.left_out.size(), 1u);
  EXPECT_THAT(v.left_out[0], HasSubstr("rbpf-slam: not ranked on fr079"));
  ASSERT_EQ(v.contestants.size(), 5u);
  const std::vector<std::pair<std::string, double>> expected = {{"cartographer", 4.0 / 3.0},
                                                                {"gmapping", 5.5 / 3.0},
                                                                {"vinyslam", 8.5 / 3.0},
                                                                {"tinyslam", 4.0},
                                                                {"hector", 5.0}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(v.contestants[i].label, expected[i].first);
    EXPECT_NEAR(v.contestants[i].mean_rank, expected[i].second, 1e-12);
  }
  // gmapping's ranks in table order (by sequence name): fr079, intel-full-rate, simulated-floor.
  EXPECT_EQ(v.used_metrics.size(), 3u);
  EXPECT_EQ(v.contestants[1].ranks, (std::vector<double>{2.5, 2.0, 1.0}));

  // Rank sums 4, 5.5, 8.5, 12, 15: 12 / (3 * 5 * 6) * 487.5 - 3 * 3 * 6 = 11; one tied pair: c = 1 - 6 / 360.
  ASSERT_TRUE(v.tested);
  EXPECT_NEAR(v.friedman.tie_correction, 1.0 - 6.0 / 360.0, 1e-12);
  const double chi2 = 11.0 / (1.0 - 6.0 / 360.0);
  EXPECT_NEAR(v.friedman.chi_square, chi2, 1e-9);
  EXPECT_NEAR(v.friedman.iman_davenport_f, 2.0 * chi2 / (12.0 - chi2), 1e-9);
  EXPECT_LT(v.friedman.iman_davenport_p, 0.001);
  // CD = 2.728 * sqrt(5 * 6 / 18) = 3.522: only hector - cartographer (3.67) reaches it; hector - gmapping is 3.17.
  EXPECT_NEAR(v.critical_difference, 2.728 * std::sqrt(30.0 / 18.0), 2e-3);
  EXPECT_EQ(v.different, (std::vector<std::pair<std::size_t, std::size_t>>{{0, 4}}));
  EXPECT_THAT(v.verdict, HasSubstr("cartographer is better than hector"));
  EXPECT_EQ(v.data_sets_for_any_difference, 0u);  // CD below k - 1 = 4
}

TEST(AcrossDataSetsTest, TooFewDataSetsSayHowManyAreNeeded) {
  // Seven contestants over two data sets of the same order except one swap: CD = 2.949 * sqrt(7 * 8 / 12) = 6.37,
  // beyond the largest possible difference (6). CD(N) = 2.949 * sqrt(56 / (6 N)): 9.01 / sqrt(N) <= 6 from N = 3
  // (CD(3) = 5.20).
  std::vector<FixtureRun> runs;
  const char* names[] = {"a", "b", "c", "d", "e", "f", "g"};
  for (int j = 0; j < 7; ++j) {
    for (const char* sequence : {"s1", "s2"}) {
      FixtureRun run = testing::MakeRun(names[j], sequence, 0);
      run.ground_truth = "exact";
      run.ape_rmse_m = 0.1 * (j + 1) + (std::string(sequence) == "s2" && j < 2 ? 0.15 * (1 - 2 * j) : 0.0);
      runs.push_back(run);
    }
  }
  const std::vector<DataSetVerdict> verdicts = Verdicts(runs);
  ASSERT_EQ(verdicts.size(), 1u);
  const DataSetVerdict& v = verdicts[0];
  ASSERT_TRUE(v.tested);
  EXPECT_GT(v.critical_difference, 6.0);
  EXPECT_TRUE(v.different.empty());
  EXPECT_EQ(v.data_sets_for_any_difference, 3u);
  EXPECT_THAT(v.verdict, HasSubstr("no pair can be told apart; at least 3 data sets are needed"));
}

TEST(AcrossDataSetsTest, TwoContestantsTakeTheSignTestAndOdometryModesAreSeparateVerdicts) {
  std::vector<FixtureRun> runs;
  for (const char* mode : {"recorded", "reference"}) {
    for (int s = 0; s < 3; ++s) {
      for (const char* name : {"a", "b"}) {
        FixtureRun run = testing::MakeRun(name, std::string(1, static_cast<char>('p' + s)), 0);
        run.odometry = mode;
        run.run_id = std::string(name) + "-" + run.sequence + "-" + mode;
        run.ground_truth = "exact";
        run.ape_rmse_m = (std::string(name) == "a" ? 0.1 : 0.2) + 0.01 * s;
        runs.push_back(run);
      }
    }
  }
  const std::vector<DataSetVerdict> verdicts = Verdicts(runs);
  ASSERT_EQ(verdicts.size(), 2u);
  for (const DataSetVerdict& v : verdicts) {
    SCOPED_TRACE(v.odometry);
    EXPECT_FALSE(v.tested);
    ASSERT_TRUE(v.sign_test);
    EXPECT_EQ(v.sign_test->wins, 3u);
    EXPECT_DOUBLE_EQ(v.sign_test->p_value, 1.0 / 8.0);
    EXPECT_THAT(v.verdict, HasSubstr("is lower on 3 of 3 data sets"));
  }
  EXPECT_NE(verdicts[0].odometry, verdicts[1].odometry);
}

}  // namespace
}  // namespace slamsweep::report
