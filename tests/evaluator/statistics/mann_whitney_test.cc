#include "evaluator/statistics/mann_whitney.h"

#include <gtest/gtest.h>

#include <vector>

namespace slamsweep::evaluator {
namespace {

// Expected values: python3 without scipy (not installed here). Exact p-values by brute force over every
// C(n1+n2, n1) split of the pooled sample (itertools.combinations), an independent route from the recurrence
// in mann_whitney.cc; normal-approximation values from the textbook formula (tie-corrected variance, 0.5
// continuity correction) evaluated with math.erfc. Critical values from the Mann-Whitney table (n1 = n2 = 5,
// two-sided alpha 0.05: U <= 2 is significant).

TEST(MannWhitneyTest, ExactFullySeparatedSmallSamples) {
  // Only 2 of the C(6,3) = 20 splits are as extreme: p = 2/20.
  const std::vector<double> x = {1, 2, 3};
  const std::vector<double> y = {4, 5, 6};
  const MannWhitneyResult r = MannWhitneyU(x, y);
  EXPECT_EQ(r.method, MannWhitneyMethod::kExact);
  EXPECT_DOUBLE_EQ(r.u_x, 0.0);
  EXPECT_DOUBLE_EQ(r.u_y, 9.0);
  EXPECT_NEAR(r.p_value, 0.1, 1e-12);
}

TEST(MannWhitneyTest, ExactMatchesTextbookCriticalValues) {
  // n1 = n2 = 5: the number of splits with U <= u is 1, 2, 4, 7 for u = 0..3 (partitions of u into at most 5 parts
  // of at most 5), of C(10, 5) = 252. U = 2: p = 2 * 4/252; U = 3: p = 2 * 7/252.
  const std::vector<double> x2 = {1, 2, 3, 4, 7};
  const std::vector<double> y = {5, 6, 8, 9, 10};
  const MannWhitneyResult u2 = MannWhitneyU(x2, y);
  EXPECT_DOUBLE_EQ(u2.u_x, 2.0);
  EXPECT_NEAR(u2.p_value, 8.0 / 252.0, 1e-12);
  EXPECT_LT(u2.p_value, 0.05);
  const std::vector<double> x3 = {1, 2, 3, 5.5, 7};  // 5.5 > 5, 7 > 5, 7 > 6
  const MannWhitneyResult u3 = MannWhitneyU(x3, y);
  EXPECT_DOUBLE_EQ(u3.u_x, 3.0);
  EXPECT_NEAR(u3.p_value, 14.0 / 252.0, 1e-12);
  EXPECT_GT(u3.p_value, 0.05);
}

TEST(MannWhitneyTest, ExactBruteForceValues) {
  const std::vector<double> x = {1.1, 2.5, 3.0, 7.2, 8.0};
  const std::vector<double> y = {4.0, 5.5, 6.1, 9.3, 10.0};
  const MannWhitneyResult r = MannWhitneyU(x, y);
  EXPECT_DOUBLE_EQ(r.u_x, 6.0);
  EXPECT_NEAR(r.p_value, 0.2222222222222222, 1e-12);  // brute force: 56/252
  // Symmetric in its arguments.
  EXPECT_NEAR(MannWhitneyU(y, x).p_value, r.p_value, 1e-15);
  EXPECT_DOUBLE_EQ(MannWhitneyU(y, x).u_x, 19.0);

  const std::vector<double> a = {0.21, 0.25, 0.19, 0.30, 0.27, 0.24};
  const std::vector<double> b = {0.11, 0.13, 0.12, 0.15, 0.10, 0.14};
  const MannWhitneyResult ab = MannWhitneyU(a, b);
  EXPECT_DOUBLE_EQ(ab.u_x, 36.0);
  EXPECT_NEAR(ab.p_value, 0.0021645021645021645, 1e-15);  // 2 / C(12, 6) = 2/924
}

TEST(MannWhitneyTest, NormalApproximationWithTies) {
  // Ties force the normal approximation: U = 3, tie term sum(t^3 - t) = 6 + 24 + 24 = 54 (values 1 x2, 2 x3, 3 x3).
  const std::vector<double> x = {1, 1, 2, 2, 3};
  const std::vector<double> y = {2, 3, 3, 4, 5};
  const MannWhitneyResult r = MannWhitneyU(x, y);
  EXPECT_EQ(r.method, MannWhitneyMethod::kNormal);
  EXPECT_DOUBLE_EQ(r.u_x, 3.0);
  EXPECT_NEAR(r.z, 1.9335101599064688, 1e-12);
  EXPECT_NEAR(r.p_value, 0.05317338271357826, 1e-12);
}

TEST(MannWhitneyTest, NormalApproximationForLargeSamples) {
  std::vector<double> low;
  std::vector<double> high;
  for (int i = 1; i <= 12; ++i) low.push_back(i);
  for (int i = 13; i <= 24; ++i) high.push_back(i);
  const MannWhitneyResult separated = MannWhitneyU(low, high);
  EXPECT_EQ(separated.method, MannWhitneyMethod::kNormal);
  EXPECT_DOUBLE_EQ(separated.u_x, 0.0);
  EXPECT_NEAR(separated.z, 4.128054424705824, 1e-12);
  EXPECT_NEAR(separated.p_value, 3.658455353897101e-05, 1e-15);

  std::vector<double> x;
  std::vector<double> y;
  for (int i = 0; i < 12; ++i) x.push_back(i);
  for (int i = 3; i < 15; ++i) y.push_back(i + 0.5);
  const MannWhitneyResult r = MannWhitneyU(x, y);
  EXPECT_DOUBLE_EQ(r.u_x, 36.0);
  EXPECT_NEAR(r.p_value, 0.04040411958822375, 1e-12);
}

TEST(MannWhitneyTest, DegenerateSamples) {
  const std::vector<double> empty;
  const std::vector<double> one = {1.0};
  EXPECT_DOUBLE_EQ(MannWhitneyU(empty, one).p_value, 1.0);
  EXPECT_DOUBLE_EQ(MannWhitneyU(one, empty).p_value, 1.0);
  // One against one: either order is equally likely, p = 2 * 1/2.
  const std::vector<double> two = {2.0};
  EXPECT_DOUBLE_EQ(MannWhitneyU(one, two).p_value, 1.0);
  // Every value equal: zero variance, no evidence.
  const std::vector<double> same = {3, 3, 3};
  EXPECT_DOUBLE_EQ(MannWhitneyU(same, same).p_value, 1.0);
}

TEST(CliffsDeltaTest, HandComputed) {
  const std::vector<double> x = {1, 2, 3};
  const std::vector<double> y = {4, 5, 6};
  EXPECT_DOUBLE_EQ(CliffsDelta(x, y), -1.0);
  EXPECT_DOUBLE_EQ(CliffsDelta(y, x), 1.0);
  // {1,1,2,2,3} vs {2,3,3,4,5}, 25 pairs: wins 3 > 2 (1); ties 2 = 2 (x2), 3 = 3 (x2) (4);
  // losses 1 < all 5 (x2 = 10), 2 < 3,3,4,5 (x2 = 8), 3 < 4,5 (2) = 20. Delta = (1 - 20) / 25.
  const std::vector<double> a = {1, 1, 2, 2, 3};
  const std::vector<double> b = {2, 3, 3, 4, 5};
  EXPECT_DOUBLE_EQ(CliffsDelta(a, b), -19.0 / 25.0);
  const std::vector<double> empty;
  EXPECT_DOUBLE_EQ(CliffsDelta(empty, b), 0.0);
}

}  // namespace
}  // namespace slamsweep::evaluator
