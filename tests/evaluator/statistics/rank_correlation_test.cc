// Spearman's rho and its pooled within-stratum form. Expected values: hand computations, the
// no-ties formula 1 - 6 sum d^2 / (n (n^2 - 1)) (an independent route), and scipy
// (scipy_reference.py, run by /usr/bin/python3) on random data with many ties.
#include "evaluator/statistics/rank_correlation.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/noise/random.h"
#include "evaluator/statistics/bootstrap.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

TEST(AverageRanksTest, TiesShareTheMeanOfTheirRanks) {
  // Sorted: 5 (rank 1), 10 (2), 20 20 (3 and 4 -> 3.5), 30 30 30 (5, 6, 7 -> 6).
  const std::vector<double> values = {10, 20, 30, 20, 5, 30, 30};
  EXPECT_EQ(AverageRanks(values), (std::vector<double>{2, 3.5, 6, 3.5, 1, 6, 6}));
  EXPECT_TRUE(AverageRanks(std::vector<double>{}).empty());
  EXPECT_EQ(AverageRanks(std::vector<double>{4, 4, 4}), (std::vector<double>{2, 2, 2}));
}

TEST(SpearmanTest, MonotoneRelationsGivePlusOrMinusOne) {
  const std::vector<double> x = {0.1, 0.5, 0.7, 2.0, 9.0};
  const std::vector<double> squared = {0.01, 0.25, 0.49, 4.0, 81.0};  // monotone, far from linear
  const std::vector<double> reversed = {5, 4, 3, 2, 1};
  EXPECT_DOUBLE_EQ(*SpearmanRho(x, squared), 1.0);
  EXPECT_DOUBLE_EQ(*SpearmanRho(x, reversed), -1.0);
}

TEST(SpearmanTest, UndefinedWithoutVariationOrPairs) {
  const std::vector<double> x = {1, 2, 3};
  EXPECT_FALSE(SpearmanRho(x, std::vector<double>{7, 7, 7}));
  EXPECT_FALSE(SpearmanRho(std::vector<double>{1}, std::vector<double>{2}));
  EXPECT_FALSE(SpearmanRho(x, std::vector<double>{1, 2}));
}

TEST(SpearmanTest, AgreesWithTheNoTiesFormula) {
  // x = 1..6, y a permutation: d = rank differences, rho = 1 - 6 sum d^2 / (n (n^2 - 1)).
  const std::vector<double> x = {1, 2, 3, 4, 5, 6};
  const std::vector<double> y = {2, 1, 4, 3, 6, 5};  // every d = +-1: sum d^2 = 6
  EXPECT_NEAR(*SpearmanRho(x, y), 1.0 - 6.0 * 6.0 / (6.0 * 35.0), 1e-15);
  const std::vector<double> z = {6, 1, 5, 2, 4, 3};  // d = 5 1 2 2 1 3: sum d^2 = 44
  EXPECT_NEAR(*SpearmanRho(x, z), 1.0 - 6.0 * 44.0 / (6.0 * 35.0), 1e-15);
}

TEST(SpearmanTest, HandComputedWithTies) {
  // x ranks 1 2.5 2.5 4, y ranks 1 2 3 4: centred (-1.5, 0, 0, 1.5) and (-1.5, -0.5, 0.5, 1.5):
  // sum xy = 4.5, sum xx = 4.5, sum yy = 5 -> rho = 4.5 / sqrt(22.5) = 0.9486832980505138.
  const std::vector<double> x = {1, 2, 2, 3};
  const std::vector<double> y = {10, 20, 30, 40};
  EXPECT_NEAR(*SpearmanRho(x, y), 0.9486832980505138, 1e-15);
}

TEST(StratifiedSpearmanTest, OneStratumIsSpearman) {
  const std::vector<double> x = {3, 1, 4, 1, 5, 9, 2, 6};
  const std::vector<double> y = {2, 7, 1, 8, 2, 8, 1, 8};
  const std::vector<std::size_t> strata(x.size(), 4);
  EXPECT_NEAR(*StratifiedSpearmanRho(x, y, strata), *SpearmanRho(x, y), 1e-15);
}

TEST(StratifiedSpearmanTest, ScalesOfOtherStrataDoNotMatter) {
  // Within each sequence the metric rises with the error, but the second sequence's metric is
  // a hundred times larger at a smaller error: ranking everything together says "opposite".
  const std::vector<double> metric = {1, 2, 3, 4, 100, 200, 300, 400};
  const std::vector<double> error = {1.0, 2.0, 3.0, 4.0, 0.1, 0.2, 0.3, 0.4};
  const std::vector<std::size_t> sequence = {0, 0, 0, 0, 1, 1, 1, 1};
  EXPECT_LT(*SpearmanRho(metric, error), 0.0);
  EXPECT_DOUBLE_EQ(*StratifiedSpearmanRho(metric, error, sequence), 1.0);
  // A singleton stratum adds nothing; a stratum constant in x leaves the others to decide.
  const std::vector<double> metric2 = {1, 2, 3, 4, 100, 100, 100, 100, 7};
  const std::vector<double> error2 = {1.0, 2.0, 3.0, 4.0, 0.1, 0.2, 0.3, 0.4, 0.0};
  const std::vector<std::size_t> sequence2 = {0, 0, 0, 0, 1, 1, 1, 1, 2};
  // Stratum 0: centred ranks (-1.5..1.5)/4 in both; stratum 1: x all 0, y (-1.5..1.5)/4.
  // sum xy = sum xx = 5/16, sum yy = 10/16: rho = (5/16) / sqrt(50/256) = 1/sqrt(2).
  EXPECT_NEAR(*StratifiedSpearmanRho(metric2, error2, sequence2), 1.0 / std::sqrt(2.0), 1e-15);
  EXPECT_FALSE(
      StratifiedSpearmanRho(std::vector<double>{1, 2}, std::vector<double>{1, 2}, std::vector<std::size_t>{0, 1}));
}

/// Runs scipy_reference.py on `cases`; null when python3 or scipy is missing.
nlohmann::json RunScipy(const nlohmann::json& cases, std::string& why) {
  const char* python = "/usr/bin/python3";
  slamsweep::testing::TempDir dir;
  slamsweep::testing::WriteFile(dir / "cases.json", cases.dump());
  const std::string command = std::string(python) + " '" + SLAMSWEEP_SCIPY_REFERENCE + "' < '" +
                              (dir / "cases.json").string() + "' > '" + (dir / "out.json").string() + "' 2> '" +
                              (dir / "err.txt").string() + "'";
  if (std::system(command.c_str()) != 0) {
    std::ifstream err(dir / "err.txt");
    why = "python3 with scipy (apt-get install python3-scipy) could not compute the reference: " +
          std::string(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>());
    return nullptr;
  }
  std::ifstream in(dir / "out.json");
  return nlohmann::json::parse(in);
}

TEST(SpearmanTest, AgreesWithScipyOnRandomDataWithTies) {
  RandomEngine engine(11);
  nlohmann::json cases = {{"spearman", nlohmann::json::array()},
                          {"pooled", nlohmann::json::array()},
                          {"quantile", nlohmann::json::array()}};
  std::vector<std::vector<double>> xs, ys;
  std::vector<std::vector<std::size_t>> strata;
  for (int c = 0; c < 40; ++c) {
    const std::size_t n = 3 + UniformIndex(engine, 60);
    // Small integer ranges give many ties; every fourth case is continuous.
    const std::uint64_t levels = c % 4 == 3 ? 1000000 : 2 + UniformIndex(engine, 6);
    std::vector<double> x(n), y(n);
    std::vector<std::size_t> s(n);
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = static_cast<double>(UniformIndex(engine, levels));
      y[i] = x[i] * (c % 2) + static_cast<double>(UniformIndex(engine, levels));  // odd cases correlate
      s[i] = UniformIndex(engine, 3);
    }
    cases["spearman"].push_back({{"x", x}, {"y", y}});
    cases["pooled"].push_back({{"x", x}, {"y", y}, {"strata", s}});
    cases["quantile"].push_back({{"values", x}, {"q", UniformUnit(engine)}});
    xs.push_back(x), ys.push_back(y), strata.push_back(s);
  }
  std::string why;
  const nlohmann::json expected = RunScipy(cases, why);
  if (expected.is_null()) {
    if (slamsweep::testing::RunningInCi()) FAIL() << why;
    GTEST_SKIP() << why;
  }
  std::size_t defined = 0;
  for (std::size_t c = 0; c < xs.size(); ++c) {
    SCOPED_TRACE(c);
    const std::optional<double> rho = SpearmanRho(xs[c], ys[c]);
    if (expected["spearman"][c].is_null()) {
      EXPECT_FALSE(rho);
    } else {
      ASSERT_TRUE(rho);
      EXPECT_NEAR(*rho, expected["spearman"][c].get<double>(), 1e-12);
      ++defined;
    }
    const std::optional<double> pooled = StratifiedSpearmanRho(xs[c], ys[c], strata[c]);
    EXPECT_EQ(pooled.has_value(), !expected["pooled"][c].is_null());
    if (pooled && !expected["pooled"][c].is_null()) {
      EXPECT_NEAR(*pooled, expected["pooled"][c].get<double>(), 1e-12);
    }
    std::vector<double> sorted = xs[c];
    std::sort(sorted.begin(), sorted.end());
    EXPECT_NEAR(InterpolatedQuantile(sorted, cases["quantile"][c]["q"].get<double>()),
                expected["quantile"][c].get<double>(), 1e-9);
  }
  EXPECT_GT(defined, 30u);
}

}  // namespace
}  // namespace slamsweep::evaluator
