#include "evaluator/sequence/flaser_fan.h"

#include <gtest/gtest.h>

#include "evaluator/core/input_error.h"
#include "evaluator/core/pose.h"

namespace slamsweep::evaluator {
namespace {

/// Direction of the last beam, in degrees.
double LastBeamDeg(const BeamFan& fan, std::size_t beams) {
  return RadToDeg(fan.angle_min_rad + static_cast<double>(beams - 1) * fan.angle_increment_rad);
}

TEST(FlaserFanTest, OddCountsSpanMinusNinetyToPlusNinetyInclusive) {
  for (std::size_t beams : {181u, 361u}) {
    const BeamFan fan = FlaserBeamFan(beams);
    EXPECT_TRUE(fan.known_layout);
    EXPECT_DOUBLE_EQ(RadToDeg(fan.angle_min_rad), -90.0);
    EXPECT_DOUBLE_EQ(RadToDeg(fan.angle_increment_rad), 180.0 / static_cast<double>(beams - 1));
    EXPECT_NEAR(LastBeamDeg(fan, beams), 90.0, 1e-9);
  }
}

TEST(FlaserFanTest, EvenCountsAreTheSameScannerWithoutItsLastBeam) {
  const BeamFan one_degree = FlaserBeamFan(180);
  EXPECT_DOUBLE_EQ(RadToDeg(one_degree.angle_min_rad), -90.0);
  EXPECT_DOUBLE_EQ(RadToDeg(one_degree.angle_increment_rad), 1.0);
  EXPECT_NEAR(LastBeamDeg(one_degree, 180), 89.0, 1e-9);

  const BeamFan half_degree = FlaserBeamFan(360);
  EXPECT_DOUBLE_EQ(RadToDeg(half_degree.angle_increment_rad), 0.5);
  EXPECT_NEAR(LastBeamDeg(half_degree, 360), 89.5, 1e-9);
  EXPECT_TRUE(half_degree.known_layout);
}

TEST(FlaserFanTest, OtherCountsAreSpreadOverHalfATurnAndMarkedAsGuessed) {
  const BeamFan fan = FlaserBeamFan(91);
  EXPECT_FALSE(fan.known_layout);
  EXPECT_DOUBLE_EQ(RadToDeg(fan.angle_increment_rad), 2.0);
  EXPECT_NEAR(LastBeamDeg(fan, 91), 90.0, 1e-9);
}

TEST(FlaserFanTest, FewerThanTwoBeamsHaveNoFan) {
  EXPECT_THROW(FlaserBeamFan(0), InputError);
  EXPECT_THROW(FlaserBeamFan(1), InputError);
}

}  // namespace
}  // namespace slamsweep::evaluator
