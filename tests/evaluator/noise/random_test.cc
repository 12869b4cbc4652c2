#include "evaluator/noise/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

namespace slamsweep::evaluator {
namespace {

TEST(RandomTest, UniformUnitUsesTheTop53BitsOfTheStandardEngine) {
  // The C++ standard fixes the first output of mt19937_64 with its default seed 5489.
  RandomEngine engine(5489u);
  const double expected = static_cast<double>(14514284786278117030ULL >> 11) / 9007199254740992.0;
  EXPECT_EQ(UniformUnit(engine), expected);
}

TEST(RandomTest, DerivedSeedsAreDistinctAndRepeatable) {
  std::set<std::uint64_t> seeds;
  for (std::uint64_t k = 0; k < 10000; ++k) seeds.insert(DeriveSeed(42, k));
  EXPECT_EQ(seeds.size(), 10000u);
  EXPECT_EQ(DeriveSeed(42, 7), DeriveSeed(42, 7));
  EXPECT_NE(DeriveSeed(42, 7), DeriveSeed(43, 7));
  EXPECT_FALSE(seeds.contains(42));
}

TEST(RandomTest, StandardNormalHasUnitVarianceAndZeroMean) {
  RandomEngine engine(1);
  constexpr int kCount = 200000;
  double sum = 0.0;
  double sum_squares = 0.0;
  int beyond_two_sigma = 0;
  for (int i = 0; i < kCount; ++i) {
    const double x = StandardNormal(engine);
    ASSERT_TRUE(std::isfinite(x));
    sum += x;
    sum_squares += x * x;
    if (std::abs(x) > 2.0) ++beyond_two_sigma;
  }
  const double mean = sum / kCount;
  EXPECT_NEAR(mean, 0.0, 0.01);
  EXPECT_NEAR(sum_squares / kCount - mean * mean, 1.0, 0.015);
  // P(|X| > 2) = 0.0455 for a normal distribution.
  EXPECT_NEAR(static_cast<double>(beyond_two_sigma) / kCount, 0.0455, 0.003);
}

TEST(RandomTest, UniformIndexSamplerDrawsWhatUniformIndexDraws) {
  // Counts where the remainder by multiplication is easy to get wrong: powers of two and their
  // neighbours, counts with rejection thresholds near 2^63, and the largest count.
  const std::uint64_t counts[] = {1,
                                  2,
                                  3,
                                  7,
                                  1000,
                                  4096,
                                  65537,
                                  (1ull << 32) - 1,
                                  (1ull << 32) + 5,
                                  (1ull << 63) - 1,
                                  1ull << 63,
                                  (1ull << 63) + 1,
                                  0xffffffffffffffffull,
                                  0x9e3779b97f4a7c15ull};
  for (const std::uint64_t count : counts) {
    SCOPED_TRACE(count);
    RandomEngine reference(count), engine(count);
    const UniformIndexSampler sampler(count);
    for (int i = 0; i < 20000; ++i) ASSERT_EQ(sampler(engine), UniformIndex(reference, count)) << i;
  }
  // Remainders of values near 2^64 by large counts, where the engine seldom goes.
  for (const std::uint64_t count : counts) {
    if (count < 2) continue;
    for (const std::uint64_t value :
         {std::uint64_t{0xffffffffffffffffull}, std::uint64_t{0xfffffffffffffffeull}, count - 1, count, count + 1}) {
      const std::uint64_t threshold = (0 - count) % count;
      if (value < threshold) continue;
      // An engine whose next draw is `value`: mt19937_64 cannot be steered, so the sampler's remainder
      // is checked against % through a sampler for the one value.
      EXPECT_EQ(UniformIndexSampler::RemainderForTesting(count, value), value % count) << count << " " << value;
    }
  }
}

TEST(RandomTest, UniformIndexCoversTheRangeEvenly) {
  RandomEngine engine(3);
  std::vector<int> counts(7, 0);
  for (int i = 0; i < 70000; ++i) {
    const std::uint64_t index = UniformIndex(engine, 7);
    ASSERT_LT(index, 7u);
    ++counts[index];
  }
  for (int count : counts) EXPECT_NEAR(count, 10000, 400);
  EXPECT_EQ(UniformIndex(engine, 0), 0u);
}

TEST(RandomTest, UniformBetweenStaysInItsInterval) {
  RandomEngine engine(9);
  for (int i = 0; i < 1000; ++i) {
    const double x = UniformBetween(engine, -2.0, 3.0);
    EXPECT_GE(x, -2.0);
    EXPECT_LT(x, 3.0);
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
