// The one-sided sign test: hand-computed binomial tails, and scipy.stats.binomtest as the independent
// reference over many (wins, pairs).
#include "evaluator/statistics/sign_test.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

TEST(SignTestTest, TenDrawsAtFivePercentNeedNineWins) {
  // P(X >= 9 | n = 10) = (C(10,9) + C(10,10)) / 1024 = 11 / 1024; P(X >= 8) = 56 / 1024 > 0.05.
  EXPECT_DOUBLE_EQ(SignTestPValue(9, 10), 11.0 / 1024.0);
  EXPECT_DOUBLE_EQ(SignTestPValue(8, 10), 56.0 / 1024.0);
  EXPECT_DOUBLE_EQ(SignTestPValue(10, 10), 1.0 / 1024.0);
  EXPECT_DOUBLE_EQ(SignTestPValue(0, 10), 1.0);
  EXPECT_EQ(SignTestWinsNeeded(10, 0.05), 9u);
  // Four pairs can never reach 5 %: 1/16 > 0.05.
  EXPECT_EQ(SignTestWinsNeeded(4, 0.05), 5u);
  EXPECT_EQ(SignTestWinsNeeded(5, 0.05), 5u);  // 1/32
}

TEST(SignTestTest, PairsTiesAndTheEchoOfTheBaseline) {
  const std::vector<double> baseline = {3, 3, 3, 3, 3, 3, 3, 3, 3, 3};
  const std::vector<double> better = {1, 1, 1, 1, 1, 1, 1, 1, 1, 5};
  const SignTestResult won = OneSidedSignTest(better, baseline);
  EXPECT_EQ(won.wins, 9u);
  EXPECT_EQ(won.losses, 1u);
  EXPECT_DOUBLE_EQ(won.p_value, 11.0 / 1024.0);
  // A program that hands back the baseline ties every pair: no sign at all, p = 1.
  const SignTestResult echo = OneSidedSignTest(baseline, baseline);
  EXPECT_EQ(echo.ties, 10u);
  EXPECT_DOUBLE_EQ(echo.p_value, 1.0);
  EXPECT_THROW(OneSidedSignTest(better, std::vector<double>{1.0}), std::invalid_argument);
}

TEST(SignTestTest, AgreesWithScipyBinomtest) {
  nlohmann::json cases = nlohmann::json::array();
  for (int pairs = 1; pairs <= 40; pairs += 3) {
    for (int wins = 0; wins <= pairs; ++wins) cases.push_back({{"wins", wins}, {"pairs", pairs}});
  }
  slamsweep::testing::TempDir dir;
  slamsweep::testing::WriteFile(dir / "cases.json", cases.dump());
  const std::string script =
      "import json, sys\nfrom scipy import stats\n"
      "cases = json.load(open(sys.argv[1]))\n"
      "print(json.dumps([stats.binomtest(c['wins'], c['pairs'], 0.5, alternative='greater').pvalue for c in cases]))\n";
  slamsweep::testing::WriteFile(dir / "binom.py", script);
  const std::string command = "/usr/bin/python3 '" + (dir / "binom.py").string() + "' '" +
                              (dir / "cases.json").string() + "' > '" + (dir / "out.json").string() + "' 2>&1";
  if (std::system(command.c_str()) != 0) {
    std::ifstream err(dir / "out.json");
    const std::string why = "python3 with scipy (apt-get install python3-scipy) could not compute the reference: " +
                            std::string(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>());
    if (slamsweep::testing::RunningInCi()) FAIL() << why;
    GTEST_SKIP() << why;
  }
  std::ifstream in(dir / "out.json");
  const nlohmann::json expected = nlohmann::json::parse(in);
  ASSERT_EQ(expected.size(), cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::size_t wins = cases[i]["wins"], pairs = cases[i]["pairs"];
    EXPECT_NEAR(SignTestPValue(wins, pairs), expected[i].get<double>(), 1e-12) << wins << " of " << pairs;
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
