// Friedman's test, Iman-Davenport's F and Nemenyi's critical difference. Expected values: a hand computation,
// Demšar's (2006) table of q_0.05, and scipy (friedman_reference.py, run by /usr/bin/python3) on random tables
// with and without ties.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/noise/random.h"
#include "evaluator/statistics/friedman.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

TEST(FriedmanTest, TiedTableByHand) {
  // Ranks per data set: 1 2 3 | 2 1 3 | 1.5 1.5 3; sums 4.5 4.5 9. 12/(3*3*4) * 121.5 - 36 = 4.5; one pair of
  // ties: correction 1 - 6 / (3*3*8) = 11/12; chi2 = 54/11. F = 2 chi2 / (6 - chi2) = 9.
  const FriedmanResult r = FriedmanTest({{1, 2, 3}, {2, 1, 3}, {1, 1, 2}});
  EXPECT_EQ(r.mean_ranks, (std::vector<double>{1.5, 1.5, 3.0}));
  EXPECT_NEAR(r.tie_correction, 11.0 / 12.0, 1e-15);
  EXPECT_NEAR(r.chi_square, 54.0 / 11.0, 1e-12);
  EXPECT_NEAR(r.iman_davenport_f, 9.0, 1e-12);
  EXPECT_FALSE(r.all_tied);
}

TEST(FriedmanTest, UnanimousAndAllTiedTables) {
  const FriedmanResult unanimous = FriedmanTest({{1, 2, 3}, {4, 5, 6}});
  EXPECT_NEAR(unanimous.chi_square, 4.0, 1e-12);  // N (k - 1)
  EXPECT_TRUE(std::isinf(unanimous.iman_davenport_f));
  EXPECT_DOUBLE_EQ(unanimous.iman_davenport_p, 0.0);
  const FriedmanResult tied = FriedmanTest({{2, 2, 2}, {5, 5, 5}});
  EXPECT_TRUE(tied.all_tied);
  EXPECT_DOUBLE_EQ(tied.iman_davenport_p, 1.0);
  EXPECT_EQ(tied.mean_ranks, (std::vector<double>{2.0, 2.0, 2.0}));
  EXPECT_THROW(FriedmanTest({{1, 2, 3}}), std::invalid_argument);
  EXPECT_THROW(FriedmanTest({{1, 2, 3}, {1, 2}}), std::invalid_argument);
  EXPECT_THROW(FriedmanTest({{1, 2, NAN}, {1, 2, 3}}), std::invalid_argument);
}

TEST(NemenyiTest, MatchesDemsarsTable) {
  // Demšar (2006), Table 5(a): q_0.05 / sqrt(2) for k = 2..10, printed to three places (two of them 7e-4 off
  // the exact quantile that scipy agrees with).
  const double table[] = {1.960, 2.343, 2.569, 2.728, 2.850, 2.949, 3.031, 3.102, 3.164};
  for (std::size_t k = 2; k <= 10; ++k) {
    SCOPED_TRACE(k);
    EXPECT_NEAR(StudentizedRangeUpperQuantile(0.05, k) / std::sqrt(2.0), table[k - 2], 1e-3);
  }
  // Seven contestants over three data sets: 2.949 * sqrt(7 * 8 / 18) = 5.20 ranks, beyond the largest possible
  // difference (6 would need every data set to agree); 14 data sets bring it under 2 ranks.
  EXPECT_NEAR(NemenyiCriticalDifference(7, 3), 5.2003, 1e-3);
  EXPECT_EQ(DataSetsNeeded(7, 2.0), 21u);
  EXPECT_GT(NemenyiCriticalDifference(7, 20), 2.0);
  EXPECT_LE(NemenyiCriticalDifference(7, 21), 2.0);
  EXPECT_EQ(DataSetsNeeded(7, 0.0), 0u);
  EXPECT_EQ(DataSetsNeeded(7, 1e-3, 0.05, 100), 0u);
}

/// Runs friedman_reference.py on `cases`; null when python3 or scipy is missing.
nlohmann::json RunFriedmanReference(const nlohmann::json& cases, std::string& why) {
  slamsweep::testing::TempDir dir;
  slamsweep::testing::WriteFile(dir / "cases.json", cases.dump());
  const std::string command = std::string("/usr/bin/python3 '") + SLAMSWEEP_FRIEDMAN_REFERENCE + "' < '" +
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

TEST(FriedmanTest, AgreesWithScipyOnRandomTables) {
  RandomEngine engine(41);
  std::vector<std::vector<std::vector<double>>> tables;
  nlohmann::json cases = {{"friedman", nlohmann::json::array()}, {"critical_difference", nlohmann::json::array()}};
  for (int c = 0; c < 40; ++c) {
    const std::size_t n = 2 + UniformIndex(engine, 11);
    const std::size_t k = 3 + UniformIndex(engine, 6);
    const bool tied = c % 2 == 0;  // small integers: ties within data sets
    std::vector<std::vector<double>> values(n, std::vector<double>(k));
    for (auto& row : values) {
      for (std::size_t j = 0; j < k; ++j) {
        // A drift with the contestant's index makes some tables significant.
        const double drift = 0.15 * static_cast<double>(c % 4) * static_cast<double>(j);
        row[j] = tied ? static_cast<double>(UniformIndex(engine, 4)) + std::round(drift) : UniformUnit(engine) + drift;
      }
    }
    bool varies = false;  // scipy's statistic divides by zero on a table of equal values only
    for (const auto& row : values)
      for (const double v : row) varies = varies || v != row.front();
    if (!varies) values[0][0] += 1.0;
    cases["friedman"].push_back({{"values", values}});
    tables.push_back(values);
  }
  struct Cd {
    std::size_t k, n;
    double alpha, at;
  };
  const std::vector<Cd> cds = {{3, 2, 0.05, 2.0},   {5, 3, 0.05, 3.5}, {7, 3, 0.05, 4.0}, {7, 12, 0.10, 1.0},
                               {10, 30, 0.01, 5.0}, {2, 5, 0.05, 0.5}, {15, 4, 0.05, 6.0}};
  for (const Cd& cd : cds)
    cases["critical_difference"].push_back({{"k", cd.k}, {"n", cd.n}, {"alpha", cd.alpha}, {"at", cd.at}});
  std::string why;
  const nlohmann::json expected = RunFriedmanReference(cases, why);
  if (expected.is_null()) {
    if (slamsweep::testing::RunningInCi()) FAIL() << why;
    GTEST_SKIP() << why;
  }
  int significant = 0, with_ties = 0;
  for (std::size_t c = 0; c < tables.size(); ++c) {
    SCOPED_TRACE(c);
    const FriedmanResult r = FriedmanTest(tables[c]);
    const nlohmann::json& e = expected["friedman"][c];
    ASSERT_EQ(r.mean_ranks.size(), e["mean_ranks"].size());
    for (std::size_t j = 0; j < r.mean_ranks.size(); ++j)
      EXPECT_NEAR(r.mean_ranks[j], e["mean_ranks"][j].get<double>(), 1e-12);
    EXPECT_NEAR(r.chi_square, e["chi_square"].get<double>(), 1e-9);
    EXPECT_NEAR(r.chi_square_p, e["chi_square_p"].get<double>(), 1e-12);
    if (e["iman_davenport_f"].is_null()) {
      EXPECT_TRUE(std::isinf(r.iman_davenport_f));
    } else {
      EXPECT_NEAR(r.iman_davenport_f, e["iman_davenport_f"].get<double>(), 1e-9 * (1.0 + r.iman_davenport_f));
    }
    EXPECT_NEAR(r.iman_davenport_p, e["iman_davenport_p"].get<double>(), 1e-12);
    significant += r.iman_davenport_p <= 0.05;
    with_ties += r.tie_correction < 1.0;
  }
  // The random tables are not all alike: some tied, some significant, some not.
  EXPECT_GT(significant, 5);
  EXPECT_LT(significant, 35);
  EXPECT_GT(with_ties, 15);
  for (std::size_t c = 0; c < cds.size(); ++c) {
    SCOPED_TRACE(c);
    const nlohmann::json& e = expected["critical_difference"][c];
    EXPECT_NEAR(StudentizedRangeUpperQuantile(cds[c].alpha, cds[c].k), e["q"].get<double>(), 1e-7);
    EXPECT_NEAR(StudentizedRangeCdf(cds[c].at, cds[c].k), e["cdf"].get<double>(), 1e-9);
    EXPECT_NEAR(NemenyiCriticalDifference(cds[c].k, cds[c].n, cds[c].alpha), e["cd"].get<double>(), 1e-7);
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
