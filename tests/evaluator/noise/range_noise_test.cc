#include "evaluator/noise/range_noise.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

// Beams alternate between a return at 5 m and no return (range_max).
std::vector<LaserScan> Scans(int scan_count, int beam_count) {
  LaserScan scan;
  scan.range_min_m = 0.1;
  scan.range_max_m = 30.0;
  scan.angle_min_rad = -1.0;
  scan.angle_increment_rad = 0.01;
  for (int i = 0; i < beam_count; ++i) scan.ranges_m.push_back(i % 2 == 0 ? 5.0f : 30.0f);
  return std::vector<LaserScan>(scan_count, scan);
}

TEST(RangeNoiseTest, ZeroNoiseLeavesScansUnchanged) {
  const std::vector<LaserScan> scans = Scans(3, 50);
  const std::vector<LaserScan> noisy = ApplyRangeNoise(scans, RangeNoise{}, 1);
  ASSERT_EQ(noisy.size(), 3u);
  for (std::size_t i = 0; i < scans.size(); ++i) EXPECT_EQ(noisy[i].ranges_m, scans[i].ranges_m);
}

TEST(RangeNoiseTest, GaussianNoiseHasSigmaAndLeavesNoReturnsAlone) {
  RangeNoise noise;
  noise.sigma_m = 0.1;
  const std::vector<LaserScan> noisy = ApplyRangeNoise(Scans(200, 1000), noise, 2);
  double sum = 0.0, sum_squares = 0.0;
  int count = 0;
  for (const LaserScan& scan : noisy) {
    for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
      if (i % 2 == 1) {
        ASSERT_EQ(scan.ranges_m[i], 30.0f);
        continue;
      }
      const double error = scan.ranges_m[i] - 5.0;
      sum += error;
      sum_squares += error * error;
      ++count;
    }
  }
  const double mean = sum / count;
  EXPECT_NEAR(mean, 0.0, 0.002);
  EXPECT_NEAR(std::sqrt(sum_squares / count - mean * mean), 0.1, 0.002);
}

TEST(RangeNoiseTest, DropoutsBecomeNoReturnsAtTheirRate) {
  RangeNoise noise;
  noise.dropout_probability = 0.3;
  const std::vector<LaserScan> noisy = ApplyRangeNoise(Scans(100, 1000), noise, 3);
  int returns = 0, beams = 0;
  for (const LaserScan& scan : noisy) {
    for (std::size_t i = 0; i < scan.ranges_m.size(); i += 2) {
      ++beams;
      if (scan.IsHit(scan.ranges_m[i])) {
        ++returns;
        EXPECT_EQ(scan.ranges_m[i], 5.0f);
      }
    }
  }
  EXPECT_NEAR(static_cast<double>(returns) / beams, 0.7, 0.01);
}

TEST(RangeNoiseTest, ShortReadingsFallBetweenMinimumAndTrueRange) {
  RangeNoise noise;
  noise.short_reading_probability = 1.0;
  noise.sigma_m = 1.0;  // must not apply to a short reading
  const std::vector<LaserScan> noisy = ApplyRangeNoise(Scans(10, 1000), noise, 4);
  double sum_of_returns = 0.0;
  int returns = 0;
  for (const LaserScan& scan : noisy) {
    for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
      const float range = scan.ranges_m[i];
      EXPECT_GE(range, 0.1f);
      EXPECT_LT(range, i % 2 == 0 ? 5.0f : 30.0f);
      if (i % 2 == 0) {
        sum_of_returns += range;
        ++returns;
      }
    }
  }
  // Uniform on [0.1, 5): mean 2.55.
  EXPECT_NEAR(sum_of_returns / returns, 2.55, 0.05);
}

TEST(RangeNoiseTest, NoisyReturnsStayReturns) {
  std::vector<LaserScan> scans = Scans(1, 2000);
  for (float& range : scans[0].ranges_m) range = 29.99f;
  RangeNoise noise;
  noise.sigma_m = 0.5;
  const std::vector<LaserScan> noisy = ApplyRangeNoise(scans, noise, 5);
  for (float range : noisy[0].ranges_m) EXPECT_TRUE(noisy[0].IsHit(range)) << range;
}

TEST(RangeNoiseTest, NoReturnRangeIsNeverAHit) {
  LaserScan scan;
  scan.range_max_m = 81.9;  // not representable as a float
  EXPECT_GE(static_cast<double>(NoReturnRangeM(81.9)), 81.9);
  EXPECT_FALSE(scan.IsHit(NoReturnRangeM(81.9)));
  EXPECT_EQ(NoReturnRangeM(30.0), 30.0f);
}

TEST(RangeNoiseTest, SameSeedSameScansDifferentSeedDifferentScans) {
  const RangeNoise noise{0.05, 0.1, 0.05};
  const std::vector<LaserScan> scans = Scans(5, 360);
  const std::vector<LaserScan> a = ApplyRangeNoise(scans, noise, 99);
  const std::vector<LaserScan> b = ApplyRangeNoise(scans, noise, 99);
  const std::vector<LaserScan> c = ApplyRangeNoise(scans, noise, 100);
  for (std::size_t i = 0; i < scans.size(); ++i) EXPECT_EQ(a[i].ranges_m, b[i].ranges_m);
  EXPECT_NE(a[0].ranges_m, c[0].ranges_m);
}

TEST(RangeNoiseTest, ValidationAndJson) {
  EXPECT_THAT(
      [] {
        ValidateRangeNoise(RangeNoise{-0.1, 0.0, 0.0});
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("sigma_m")));
  EXPECT_THAT(
      [] {
        ValidateRangeNoise(RangeNoise{0.0, 1.5, 0.0});
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("dropout_probability")));
  EXPECT_THAT(
      [] {
        ApplyRangeNoise(Scans(1, 1), RangeNoise{0.0, 0.0, std::nan("")}, 1);
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("short_reading_probability")));

  std::vector<LaserScan> inverted = Scans(1, 3);
  inverted[0].range_min_m = 40.0;
  EXPECT_THAT([&] { ApplyRangeNoise(inverted, RangeNoise{}, 1); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("range_max_m")));

  const RangeNoise noise{0.02, 0.01, 0.005};
  const nlohmann::json json = noise;
  EXPECT_EQ(json.at("model"), "range_noise");
  EXPECT_EQ(json.at("sigma_m"), 0.02);
  EXPECT_EQ(json.get<RangeNoise>(), noise);
  EXPECT_THAT(
      [] {
        RangeNoiseFromJson(nlohmann::json{{"sigma", 0.1}});
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("range_noise.sigma: unknown option")));
  EXPECT_THAT(
      [] {
        RangeNoiseFromJson(nlohmann::json{{"dropout_probability", 2}});
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("range_noise.dropout_probability")));
}

}  // namespace
}  // namespace slamsweep::evaluator
