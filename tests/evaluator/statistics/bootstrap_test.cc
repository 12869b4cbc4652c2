// The stratified percentile bootstrap of the pooled rank correlation. The expected distribution
// comes from brute force: for a small sample every one of the n^n equally likely resamples is
// enumerated, which gives the exact bootstrap distribution the Monte Carlo draws approximate.
#include "evaluator/statistics/bootstrap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "evaluator/noise/random.h"

namespace slamsweep::evaluator {
namespace {

/// The bootstrap as first written: every resample copied and ranked by sorting (PooledRankCorrelation).
/// The counting ranks of BootstrapPooledRankCorrelation must give exactly its interval.
std::optional<BootstrapInterval> SortingBootstrap(const std::vector<PairedStratum>& strata,
                                                  const BootstrapOptions& options) {
  RandomEngine engine(options.seed);
  std::vector<PairedStratum> resample = strata;
  std::vector<double> replicates;
  for (std::size_t r = 0; r < options.resamples; ++r) {
    for (std::size_t s = 0; s < strata.size(); ++s) {
      const std::size_t n = strata[s].x.size();
      for (std::size_t k = 0; k < n; ++k) {
        const auto drawn = static_cast<std::size_t>(UniformIndex(engine, n));
        resample[s].x[k] = strata[s].x[drawn];
        resample[s].y[k] = strata[s].y[drawn];
      }
    }
    if (const std::optional<double> rho = PooledRankCorrelation(resample)) replicates.push_back(*rho);
  }
  if (replicates.empty() ||
      static_cast<double>(replicates.size()) < options.min_defined_fraction * static_cast<double>(options.resamples)) {
    return std::nullopt;
  }
  std::sort(replicates.begin(), replicates.end());
  return BootstrapInterval{InterpolatedQuantile(replicates, (1.0 - options.confidence) / 2.0),
                           InterpolatedQuantile(replicates, (1.0 + options.confidence) / 2.0), options.resamples,
                           replicates.size()};
}

TEST(BootstrapTest, CountingRanksGiveExactlyTheIntervalOfSortingEveryResample) {
  RandomEngine engine(5);
  for (int c = 0; c < 30; ++c) {
    SCOPED_TRACE(c);
    // 1-4 strata of 1-40 pairs, many ties (few levels), -0.0 beside 0.0, some strata correlated.
    std::vector<PairedStratum> strata(1 + UniformIndex(engine, 4));
    for (PairedStratum& stratum : strata) {
      const std::size_t n = 1 + UniformIndex(engine, 40);
      const std::uint64_t levels = 2 + UniformIndex(engine, c % 3 == 0 ? 1000 : 6);
      for (std::size_t k = 0; k < n; ++k) {
        const double x = static_cast<double>(UniformIndex(engine, levels));
        stratum.x.push_back(x == 0.0 && k % 2 == 0 ? -0.0 : x);
        stratum.y.push_back(x * (c % 2) + static_cast<double>(UniformIndex(engine, levels)));
      }
    }
    BootstrapOptions options;
    options.resamples = 300;
    options.seed = 100 + static_cast<std::uint64_t>(c);
    const std::optional<BootstrapInterval> expected = SortingBootstrap(strata, options);
    const std::optional<BootstrapInterval> interval = BootstrapPooledRankCorrelation(strata, options);
    ASSERT_EQ(interval.has_value(), expected.has_value());
    if (!expected) continue;
    EXPECT_EQ(interval->low, expected->low);
    EXPECT_EQ(interval->high, expected->high);
    EXPECT_EQ(interval->defined, expected->defined);
  }
}

TEST(InterpolatedQuantileTest, HandComputed) {
  const std::vector<double> sorted = {1, 2, 3, 4};
  EXPECT_DOUBLE_EQ(InterpolatedQuantile(sorted, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(InterpolatedQuantile(sorted, 0.25), 1.75);  // position 0.75
  EXPECT_DOUBLE_EQ(InterpolatedQuantile(sorted, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(InterpolatedQuantile(sorted, 1.0), 4.0);
  EXPECT_DOUBLE_EQ(InterpolatedQuantile({7.0}, 0.3), 7.0);
}

TEST(BootstrapTest, TheSameSeedGivesTheSameInterval) {
  const std::vector<PairedStratum> strata = {{{1, 2, 3, 4, 5, 6, 7, 8, 9}, {2, 1, 3, 5, 4, 6, 9, 7, 8}}};
  const auto a = BootstrapPooledRankCorrelation(strata);
  const auto b = BootstrapPooledRankCorrelation(strata);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->low, b->low);
  EXPECT_EQ(a->high, b->high);
  EXPECT_EQ(a->resamples, 2000u);
  BootstrapOptions other;
  other.seed = 1;
  const auto c = BootstrapPooledRankCorrelation(strata, other);
  ASSERT_TRUE(c);
  EXPECT_TRUE(c->low != a->low || c->high != a->high);
  // The point estimate (rho = 0.9) lies inside, the bounds are ordered and within [-1, 1].
  EXPECT_LE(a->low, 0.9);
  EXPECT_GE(a->high, 0.9);
  EXPECT_GE(a->low, -1.0);
  EXPECT_LE(a->high, 1.0);
}

TEST(BootstrapTest, APerfectRelationStaysPerfectAndResamplesStayInTheirStratum) {
  // Every resample of a strictly monotone relation is monotone (ties in both at once): rho = 1.
  // The second stratum's values would break the order if a resample mixed the strata.
  const std::vector<PairedStratum> strata = {{{1, 2, 3, 4, 5, 6, 7, 8}, {10, 20, 30, 40, 50, 60, 70, 80}},
                                             {{5, 6, 7}, {0.1, 0.2, 0.3}}};
  const auto interval = BootstrapPooledRankCorrelation(strata);
  ASSERT_TRUE(interval);
  EXPECT_DOUBLE_EQ(interval->low, 1.0);
  EXPECT_DOUBLE_EQ(interval->high, 1.0);
}

TEST(BootstrapTest, UndefinedWhenTooManyResamplesAreConstant) {
  // Two distinct x values, one of them once in 8: a resample misses it with probability
  // (7/8)^8 = 0.344 and is then constant in x, so about 65.6 % of the resamples are defined.
  const std::vector<PairedStratum> strata = {{{0, 0, 0, 0, 0, 0, 0, 1}, {1, 2, 3, 4, 5, 6, 7, 8}}};
  const auto interval = BootstrapPooledRankCorrelation(strata);
  ASSERT_TRUE(interval);
  EXPECT_NEAR(static_cast<double>(interval->defined) / 2000.0, 1.0 - std::pow(7.0 / 8.0, 8.0), 0.03);
  BootstrapOptions strict;
  strict.min_defined_fraction = 0.9;
  EXPECT_FALSE(BootstrapPooledRankCorrelation(strata, strict));
  BootstrapOptions none;
  none.resamples = 0;
  EXPECT_FALSE(BootstrapPooledRankCorrelation({{{1, 2, 3}, {1, 2, 3}}}, none));
}

TEST(BootstrapTest, MatchesTheExactBootstrapDistribution) {
  // n = 6: all 6^6 = 46656 resamples, each equally likely, give the exact distribution of rho*.
  const PairedStratum sample{{1, 2, 3, 4, 5, 6}, {1.5, 1.0, 3.2, 2.9, 6.0, 4.4}};
  const std::size_t n = sample.x.size();
  std::map<double, std::size_t> exact;  // rho* -> number of resamples
  std::size_t defined = 0, total = 0;
  std::vector<std::size_t> index(n, 0);
  for (;;) {
    PairedStratum drawn;
    for (std::size_t k = 0; k < n; ++k) drawn.x.push_back(sample.x[index[k]]), drawn.y.push_back(sample.y[index[k]]);
    ++total;
    if (const auto rho = PooledRankCorrelation({drawn})) {
      ++exact[*rho];
      ++defined;
    }
    std::size_t k = 0;
    while (k < n && ++index[k] == n) index[k++] = 0;
    if (k == n) break;
  }
  ASSERT_EQ(total, 46656u);
  // The exact probability of rho* < v and <= v among defined resamples.
  const auto below = [&](double v, bool inclusive) {
    std::size_t count = 0;
    for (const auto& [rho, m] : exact) count += (rho < v || (inclusive && rho == v)) ? m : 0;
    return static_cast<double>(count) / static_cast<double>(defined);
  };
  BootstrapOptions options;
  options.resamples = 40000;
  const auto interval = BootstrapPooledRankCorrelation({sample}, options);
  ASSERT_TRUE(interval);
  // The share of defined resamples: exact value within Monte Carlo error (sd about 0.001).
  EXPECT_NEAR(static_cast<double>(interval->defined) / options.resamples,
              static_cast<double>(defined) / static_cast<double>(total), 0.006);
  // Each bound sits where the exact distribution function crosses 2.5 % and 97.5 %.
  constexpr double kTolerance = 0.006;
  EXPECT_LE(below(interval->low, false), 0.025 + kTolerance);
  EXPECT_GE(below(interval->low, true), 0.025 - kTolerance);
  EXPECT_LE(below(interval->high, false), 0.975 + kTolerance);
  EXPECT_GE(below(interval->high, true), 0.975 - kTolerance);
}

}  // namespace
}  // namespace slamsweep::evaluator
