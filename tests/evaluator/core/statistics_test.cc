#include "evaluator/core/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

TEST(StatisticsTest, MatchesHandComputedValues) {
  const std::vector<double> errors = {1.0, 2.0, 3.0, 4.0};
  const ErrorStatistics s = ComputeStatistics(errors);
  EXPECT_EQ(s.n, 4u);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.median, 2.5);  // mean of the middle two, as numpy does
  EXPECT_DOUBLE_EQ(s.sse, 30.0);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(7.5));
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(1.25));  // population std (ddof = 0)
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
}

TEST(StatisticsTest, OddCountMedianIsMiddleValue) {
  const std::vector<double> errors = {9.0, 1.0, 5.0};
  EXPECT_DOUBLE_EQ(ComputeStatistics(errors).median, 5.0);
}

TEST(StatisticsTest, EmptyInputIsAnError) { EXPECT_THROW(ComputeStatistics({}), InputError); }

TEST(StatisticsTest, JsonRoundTrip) {
  const std::vector<double> errors = {0.5, 0.25};
  const ErrorStatistics s = ComputeStatistics(errors);
  const nlohmann::json j = s;
  EXPECT_EQ(j.at("n"), 2);
  const auto back = j.get<ErrorStatistics>();
  EXPECT_DOUBLE_EQ(back.rmse, s.rmse);
  EXPECT_DOUBLE_EQ(back.median, s.median);
}

}  // namespace
}  // namespace slamsweep::evaluator
