// The rank tests that compare two rows of a report (Mann-Whitney U one- and two-sided, Wilcoxon signed-rank)
// and Holm's correction. Expected values: hand computations of the exact distributions, and scipy /
// statsmodels (rank_tests_reference.py, run by /usr/bin/python3) on random samples with and without ties.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/noise/random.h"
#include "evaluator/statistics/holm.h"
#include "evaluator/statistics/mann_whitney.h"
#include "evaluator/statistics/mean_interval.h"
#include "evaluator/statistics/wilcoxon_signed_rank.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

TEST(WilcoxonTest, FivePairsAllBetterReachOneOverThirtyTwo) {
  const std::vector<double> best = {1.0, 2.0, 3.0, 4.0, 5.0};
  const std::vector<double> runner_up = {1.5, 2.7, 3.1, 4.9, 5.2};  // |d| 0.5 0.7 0.1 0.9 0.2: no ties
  const WilcoxonResult r = WilcoxonSignedRank(best, runner_up, Alternative::kLess);
  EXPECT_EQ(r.method, MannWhitneyMethod::kExact);
  EXPECT_EQ(r.pairs_used, 5u);
  EXPECT_DOUBLE_EQ(r.w_plus, 0.0);
  EXPECT_DOUBLE_EQ(r.w_minus, 15.0);
  EXPECT_DOUBLE_EQ(r.p_value, 1.0 / 32.0);
  EXPECT_DOUBLE_EQ(WilcoxonMinimumOneSidedP(5), 1.0 / 32.0);
  // The other direction has every sign against it: P(W- >= 0) = 1.
  EXPECT_DOUBLE_EQ(WilcoxonSignedRank(best, runner_up, Alternative::kGreater).p_value, 1.0);
}

TEST(WilcoxonTest, IdenticalRunsAreTiesNotEvidence) {
  const std::vector<double> a = {0.2, 0.2, 0.2, 0.2, 0.2};
  const WilcoxonResult r = WilcoxonSignedRank(a, a, Alternative::kLess);
  EXPECT_EQ(r.pairs_used, 0u);
  EXPECT_EQ(r.zero_pairs, 5u);
  EXPECT_DOUBLE_EQ(r.p_value, 1.0);
  EXPECT_THROW(WilcoxonSignedRank(a, std::vector<double>{1.0}), std::invalid_argument);
}

TEST(WilcoxonTest, ExactTailByHandForFourPairs) {
  // d = -0.1, -0.3, +0.2, -0.4: ranks 1, 3, 2, 4; W+ = 2. Of the 16 sign patterns of ranks 1..4, those with
  // W+ <= 2 are {}, {1}, {2}: P = 3/16 one-sided (x lower).
  const std::vector<double> x = {1.0, 1.0, 1.2, 1.0};
  const std::vector<double> y = {1.1, 1.3, 1.0, 1.4};
  const WilcoxonResult r = WilcoxonSignedRank(x, y, Alternative::kLess);
  EXPECT_DOUBLE_EQ(r.w_plus, 2.0);
  EXPECT_NEAR(r.p_value, 3.0 / 16.0, 1e-15);
  EXPECT_NEAR(WilcoxonSignedRank(x, y).p_value, 6.0 / 16.0, 1e-15);
}

TEST(WilcoxonTest, ZeroDifferencesAreDropped) {
  const std::vector<double> x = {1.0, 1.0, 1.2, 1.0, 7.0};
  const std::vector<double> y = {1.1, 1.3, 1.0, 1.4, 7.0};
  const WilcoxonResult r = WilcoxonSignedRank(x, y, Alternative::kLess);
  EXPECT_EQ(r.zero_pairs, 1u);
  EXPECT_EQ(r.pairs_used, 4u);
  EXPECT_NEAR(r.p_value, 3.0 / 16.0, 1e-15);  // as ExactTailByHandForFourPairs
}

TEST(MannWhitneyOneSidedTest, SeparatedSamplesReachTheMinimum) {
  const std::vector<double> low = {1, 2, 3, 4, 5};
  const std::vector<double> high = {6, 7, 8, 9, 10};
  EXPECT_NEAR(MannWhitneyU(low, high, Alternative::kLess).p_value, 1.0 / 252.0, 1e-15);
  EXPECT_NEAR(MannWhitneyMinimumOneSidedP(5, 5), 1.0 / 252.0, 1e-15);
  EXPECT_NEAR(MannWhitneyU(low, high).p_value, 2.0 / 252.0, 1e-15);
  EXPECT_DOUBLE_EQ(MannWhitneyU(low, high, Alternative::kGreater).p_value, 1.0);
  EXPECT_NEAR(MannWhitneyMinimumOneSidedP(3, 2), 1.0 / 10.0, 1e-15);
}

TEST(HolmTest, HandComputedStepDown) {
  // Sorted 0.01, 0.02, 0.03, 0.5: times 4, 3, 2, 1 = 0.04, 0.06, 0.06, 0.5 (monotone already).
  const std::vector<double> p = {0.03, 0.5, 0.01, 0.02};
  const std::vector<double> adjusted = HolmAdjusted(p);
  ASSERT_EQ(adjusted.size(), 4u);
  EXPECT_NEAR(adjusted[0], 0.06, 1e-15);
  EXPECT_NEAR(adjusted[1], 0.5, 1e-15);
  EXPECT_NEAR(adjusted[2], 0.04, 1e-15);
  EXPECT_NEAR(adjusted[3], 0.06, 1e-15);
  // Monotonicity: a later, larger p multiplied by less can not fall below an earlier adjusted value.
  const std::vector<double> q = HolmAdjusted(std::vector<double>{0.02, 0.021});
  EXPECT_NEAR(q[0], 0.04, 1e-15);
  EXPECT_NEAR(q[1], 0.04, 1e-15);
  EXPECT_EQ(BonferroniAdjusted(std::vector<double>{0.01, 0.4}), (std::vector<double>{0.02, 0.8}));
  EXPECT_TRUE(HolmAdjusted(std::vector<double>{}).empty());
}

TEST(StudentTIntervalTest, AgreesWithScipyTInterval) {
  // scipy.stats.t.interval(0.95, n - 1, loc=mean, scale=scipy.stats.sem(values)), computed once.
  const std::optional<MeanInterval> five = StudentTInterval(std::vector<double>{0.12, 0.15, 0.11, 0.19, 0.13});
  ASSERT_TRUE(five);
  EXPECT_NEAR(five->mean, 0.14, 1e-15);
  EXPECT_NEAR(five->low, 0.1007351367704488, 1e-12);
  EXPECT_NEAR(five->high, 0.1792648632295512, 1e-12);
  const std::optional<MeanInterval> two = StudentTInterval(std::vector<double>{1.0, 3.0});
  ASSERT_TRUE(two);
  EXPECT_NEAR(two->low, -10.706204736432095, 1e-9);
  EXPECT_NEAR(two->high, 14.706204736432095, 1e-9);
  EXPECT_FALSE(StudentTInterval(std::vector<double>{1.0}));
  const std::optional<MeanInterval> flat = StudentTInterval(std::vector<double>{2.0, 2.0, 2.0});
  ASSERT_TRUE(flat);
  EXPECT_DOUBLE_EQ(flat->low, 2.0);
  EXPECT_DOUBLE_EQ(flat->high, 2.0);
}

/// Runs rank_tests_reference.py on `cases`; null when python3, scipy or statsmodels is missing.
nlohmann::json RunReference(const nlohmann::json& cases, std::string& why) {
  slamsweep::testing::TempDir dir;
  slamsweep::testing::WriteFile(dir / "cases.json", cases.dump());
  const std::string command = std::string("/usr/bin/python3 '") + SLAMSWEEP_RANK_TESTS_REFERENCE + "' < '" +
                              (dir / "cases.json").string() + "' > '" + (dir / "out.json").string() + "' 2> '" +
                              (dir / "err.txt").string() + "'";
  if (std::system(command.c_str()) != 0) {
    std::ifstream err(dir / "err.txt");
    why =
        "python3 with scipy and statsmodels (apt-get install python3-scipy python3-statsmodels) could not "
        "compute the reference: " +
        std::string(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>());
    return nullptr;
  }
  std::ifstream in(dir / "out.json");
  return nlohmann::json::parse(in);
}

const char* AlternativeName(Alternative a) {
  return a == Alternative::kLess ? "less" : a == Alternative::kGreater ? "greater" : "two-sided";
}

bool HasTies(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return std::adjacent_find(values.begin(), values.end()) != values.end();
}

TEST(RankTestsTest, AgreeWithScipyAndStatsmodelsOnRandomSamples) {
  RandomEngine engine(29);
  nlohmann::json cases = {{"mann_whitney", nlohmann::json::array()},
                          {"wilcoxon", nlohmann::json::array()},
                          {"holm", nlohmann::json::array()}};
  struct Case {
    std::vector<double> x, y;
    Alternative alternative;
  };
  std::vector<Case> mw, wx;
  std::vector<std::vector<double>> holm;
  const Alternative alternatives[] = {Alternative::kLess, Alternative::kGreater, Alternative::kTwoSided};
  for (int c = 0; c < 60; ++c) {
    const Alternative alternative = alternatives[c % 3];
    // Small integer ranges give ties (the normal approximation); every other case is continuous, and small
    // continuous samples take the exact distributions.
    const bool tied = c % 2 == 0;
    const std::size_t n_x = 2 + UniformIndex(engine, c < 30 ? 9 : 30);
    const std::size_t n_y = 2 + UniformIndex(engine, c < 30 ? 9 : 30);
    const double shift = 0.3 * static_cast<double>(c % 5);
    auto draw = [&](double offset) {
      return tied ? static_cast<double>(UniformIndex(engine, 5)) + std::round(offset) : UniformUnit(engine) + offset;
    };
    Case m{{}, {}, alternative};
    for (std::size_t i = 0; i < n_x; ++i) m.x.push_back(draw(0.0));
    for (std::size_t i = 0; i < n_y; ++i) m.y.push_back(draw(shift));
    std::vector<double> pooled = m.x;
    pooled.insert(pooled.end(), m.y.begin(), m.y.end());
    const bool mw_exact = !HasTies(pooled) && n_x <= kMannWhitneyExactMaxSize && n_y <= kMannWhitneyExactMaxSize;
    cases["mann_whitney"].push_back({{"x", m.x},
                                     {"y", m.y},
                                     {"alternative", AlternativeName(alternative)},
                                     {"method", mw_exact ? "exact" : "asymptotic"}});
    mw.push_back(m);

    // Zero differences are dropped here (scipy leaves the exact distribution when it sees one; the drop itself
    // is checked by ZeroDifferencesAreDropped).
    Case w{{}, {}, alternative};
    std::vector<double> magnitudes;
    for (std::size_t i = 0; i < n_x; ++i) {
      const double x = draw(0.0);
      const double y = x + draw(shift) - (tied ? 2.0 : 0.5);
      if (y == x) continue;
      w.x.push_back(x), w.y.push_back(y), magnitudes.push_back(std::abs(y - x));
    }
    if (magnitudes.empty()) w.x.push_back(0.0), w.y.push_back(1.0), magnitudes.push_back(1.0);
    const bool wx_exact = !HasTies(magnitudes) && magnitudes.size() <= kWilcoxonExactMaxPairs;
    cases["wilcoxon"].push_back({{"x", w.x},
                                 {"y", w.y},
                                 {"alternative", AlternativeName(alternative)},
                                 {"method", wx_exact ? "exact" : "approx"}});
    wx.push_back(w);

    std::vector<double> p;
    for (int i = 0; i < 1 + c % 7; ++i) p.push_back(UniformUnit(engine) * (c % 3 == 0 ? 0.05 : 1.0));
    cases["holm"].push_back({{"p", p}});
    holm.push_back(p);
  }
  std::string why;
  const nlohmann::json expected = RunReference(cases, why);
  if (expected.is_null()) {
    if (slamsweep::testing::RunningInCi()) FAIL() << why;
    GTEST_SKIP() << why;
  }
  for (std::size_t c = 0; c < mw.size(); ++c) {
    SCOPED_TRACE(c);
    EXPECT_NEAR(MannWhitneyU(mw[c].x, mw[c].y, mw[c].alternative).p_value, expected["mann_whitney"][c].get<double>(),
                1e-12);
    EXPECT_NEAR(WilcoxonSignedRank(wx[c].x, wx[c].y, wx[c].alternative).p_value, expected["wilcoxon"][c].get<double>(),
                1e-12);
    const std::vector<double> adjusted = HolmAdjusted(holm[c]);
    for (std::size_t i = 0; i < adjusted.size(); ++i) {
      EXPECT_NEAR(adjusted[i], expected["holm"][c][i].get<double>(), 1e-15);
    }
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
