#include "evaluator/noise/odometry_noise.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "evaluator/core/input_error.h"
#include "evaluator/noise/random.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

// A trajectory with curves, standstill, turning in place and driving backwards.
Trajectory VariedReference() {
  Trajectory reference;
  double x = 1.5, y = -2.0, yaw = 0.3;
  for (int i = 0; i < 2000; ++i) {
    reference.Add(0.1 * i, Pose::Planar(x, y, yaw));
    const int phase = (i / 100) % 4;
    const double speed = phase == 0 ? 0.05 : phase == 1 ? 0.0 : phase == 2 ? -0.03 : 0.08;
    const double turn = phase == 1 ? 0.05 : 0.02 * std::sin(0.01 * i);
    yaw += turn;
    x += speed * std::cos(yaw);
    y += speed * std::sin(yaw);
  }
  return reference;
}

Trajectory StraightLine(int steps, double step_m) {
  Trajectory reference;
  for (int i = 0; i <= steps; ++i) reference.Add(i, Pose::Planar(step_m * i, 0.0, 0.0));
  return reference;
}

struct Moments {
  double mean = 0.0;
  double std = 0.0;
};

Moments MomentsOf(const std::vector<double>& values) {
  double sum = 0.0, sum_squares = 0.0;
  for (double v : values) {
    sum += v;
    sum_squares += v * v;
  }
  Moments moments;
  moments.mean = sum / values.size();
  moments.std = std::sqrt(sum_squares / values.size() - moments.mean * moments.mean);
  return moments;
}

TEST(OdometryNoiseTest, ZeroNoiseReproducesTheReferenceExactly) {
  const Trajectory reference = VariedReference();
  const Trajectory odometry = ApplyOdometryNoise(reference, OdometryNoise{}, 123);
  ASSERT_EQ(odometry.size(), reference.size());
  for (std::size_t i = 0; i < reference.size(); ++i) {
    EXPECT_EQ(odometry.stamps_s()[i], reference.stamps_s()[i]);
    EXPECT_EQ(odometry.poses()[i].position, reference.poses()[i].position) << "pose " << i;
    EXPECT_EQ(odometry.poses()[i].orientation.coeffs(), reference.poses()[i].orientation.coeffs()) << "pose " << i;
  }
}

TEST(OdometryNoiseTest, TranslationNoiseHasTheModelsStandardDeviation) {
  // Only alpha3: the translation of each 0.1 m step gets variance alpha3 * 0.1^2, i.e.
  // std = sqrt(0.04) * 0.1 = 0.02 m, and the heading must not change at all.
  constexpr double kStep = 0.1;
  OdometryNoise noise;
  noise.alpha3 = 0.04;
  const Trajectory odometry = ApplyOdometryNoise(StraightLine(40000, kStep), noise, 7);
  std::vector<double> errors;
  for (std::size_t i = 1; i < odometry.size(); ++i) {
    const Pose step = Relative(odometry.poses()[i - 1], odometry.poses()[i]);
    ASSERT_NEAR(step.position.y(), 0.0, 1e-9);
    ASSERT_NEAR(step.Yaw(), 0.0, 1e-12);
    errors.push_back(step.position.x() - kStep);
  }
  const Moments moments = MomentsOf(errors);
  EXPECT_NEAR(moments.std, 0.02, 0.02 * 0.03);
  EXPECT_NEAR(moments.mean, 0.0, 4.0 * 0.02 / std::sqrt(errors.size()));
}

TEST(OdometryNoiseTest, RotationNoiseOfTurningInPlace) {
  // Turning in place by 0.2 rad per step: rot1 = 0, rot2 = 0.2, so with alpha1 alone the yaw
  // error has std sqrt(0.25) * 0.2 = 0.1 rad and alpha4 adds translation std sqrt(0.01) * 0.2.
  Trajectory reference;
  for (int i = 0; i <= 40000; ++i) reference.Add(i, Pose::Planar(2.0, 3.0, NormalizeAngleRad(0.2 * i)));
  OdometryNoise noise;
  noise.alpha1 = 0.25;
  noise.alpha4 = 0.01;
  const Trajectory odometry = ApplyOdometryNoise(reference, noise, 11);
  std::vector<double> yaw_errors, trans_errors;
  for (std::size_t i = 1; i < odometry.size(); ++i) {
    const Pose step = Relative(odometry.poses()[i - 1], odometry.poses()[i]);
    yaw_errors.push_back(NormalizeAngleRad(step.Yaw() - 0.2));
    trans_errors.push_back(step.position.x());
  }
  EXPECT_NEAR(MomentsOf(yaw_errors).std, 0.1, 0.003);
  EXPECT_NEAR(MomentsOf(trans_errors).std, 0.02, 0.0006);
}

TEST(OdometryNoiseTest, SystematicDriftAndScaleAccumulateWithDistance) {
  // 100 m straight ahead: a drift of 0.01 rad/m turns the odometry heading by 1 rad in total,
  // and a scale error of 10 % makes the distance 110 m.
  OdometryNoise drift;
  drift.drift_heading_rad_per_m = 0.01;
  const Trajectory turned = ApplyOdometryNoise(StraightLine(1000, 0.1), drift, 1);
  EXPECT_NEAR(turned.poses().back().Yaw(), 1.0, 1e-9);

  OdometryNoise scale;
  scale.scale_error = 0.1;
  const Trajectory longer = ApplyOdometryNoise(StraightLine(1000, 0.1), scale, 1);
  EXPECT_NEAR(longer.poses().back().position.x(), 110.0, 1e-9);
  EXPECT_NEAR(longer.poses().back().position.y(), 0.0, 1e-9);
}

TEST(OdometryNoiseTest, SameSeedSameOutputDifferentSeedDifferentOutput) {
  OdometryNoise noise{0.05, 0.01, 0.02, 0.01, 0.001, 0.02};
  const Trajectory reference = VariedReference();
  const Trajectory a = ApplyOdometryNoise(reference, noise, DeriveSeed(5, 0));
  const Trajectory b = ApplyOdometryNoise(reference, noise, DeriveSeed(5, 0));
  const Trajectory c = ApplyOdometryNoise(reference, noise, DeriveSeed(5, 1));
  bool differs = false;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    ASSERT_EQ(a.poses()[i].position, b.poses()[i].position);
    ASSERT_EQ(a.poses()[i].orientation.coeffs(), b.poses()[i].orientation.coeffs());
    differs = differs || a.poses()[i].position != c.poses()[i].position;
  }
  EXPECT_TRUE(differs);
  EXPECT_EQ(a.poses().front().position, reference.poses().front().position);
}

TEST(OdometryNoiseTest, DecomposesAStepIntoRotationTranslationRotation) {
  const OdometryIncrement step = DecomposeOdometry(Pose::Planar(1, 1, std::numbers::pi / 2), Pose::Planar(2, 1, 0.0));
  EXPECT_NEAR(step.rot1_rad, -std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(step.trans_m, 1.0, 1e-12);
  EXPECT_NEAR(step.rot2_rad, 0.0, 1e-12);
  const OdometryIncrement jitter = DecomposeOdometry(Pose::Planar(0, 0, 0), Pose::Planar(-0.001, 0.001, 0.3));
  EXPECT_EQ(jitter.rot1_rad, 0.0);
  EXPECT_NEAR(jitter.rot2_rad, 0.3, 1e-12);
}

TEST(OdometryNoiseTest, RejectsInvalidParametersNamingTheField) {
  OdometryNoise negative;
  negative.alpha2 = -0.1;
  EXPECT_THAT([&] { ValidateOdometryNoise(negative); }, ::testing::ThrowsMessage<InputError>(HasSubstr("alpha2")));
  OdometryNoise nan;
  nan.drift_heading_rad_per_m = std::nan("");
  EXPECT_THAT([&] { ApplyOdometryNoise(StraightLine(3, 1.0), nan, 1); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("drift_heading_rad_per_m")));
  OdometryNoise collapse;
  collapse.scale_error = -1.0;
  EXPECT_THAT([&] { ValidateOdometryNoise(collapse); }, ::testing::ThrowsMessage<InputError>(HasSubstr("scale_error")));
}

TEST(OdometryNoiseTest, JsonRoundTripAndStrictReading) {
  const OdometryNoise noise{0.1, 0.2, 0.3, 0.4, 0.005, -0.01};
  const nlohmann::json json = noise;
  EXPECT_EQ(json.at("model"), "odometry_motion_model");
  EXPECT_EQ(json.at("alpha3"), 0.3);
  EXPECT_EQ(json.get<OdometryNoise>(), noise);
  EXPECT_EQ(OdometryNoiseFromJson(nlohmann::json::object()), OdometryNoise{});

  EXPECT_THAT(
      [] {
        OdometryNoiseFromJson(nlohmann::json{{"alpha5", 1.0}});
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("odometry_noise.alpha5: unknown option")));
  EXPECT_THAT(
      [] {
        OdometryNoiseFromJson(nlohmann::json{{"alpha1", "big"}});
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("odometry_noise.alpha1: expected a number")));
  EXPECT_THAT(
      [] {
        OdometryNoiseFromJson(nlohmann::json{{"alpha1", -1}}, "sweep.noise");
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("sweep.noise.alpha1")));
  EXPECT_THAT(
      [] {
        OdometryNoiseFromJson(nlohmann::json{{"model", "velocity"}});
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("odometry_noise.model")));
  EXPECT_THROW(OdometryNoiseFromJson(nlohmann::json::array()), InputError);
}

}  // namespace
}  // namespace slamsweep::evaluator
