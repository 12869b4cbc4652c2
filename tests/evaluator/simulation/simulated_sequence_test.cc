#include "evaluator/simulation/simulated_sequence.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

SimulationOptions SmallBuilding() {
  SimulationOptions options;
  options.floor_plan.rooms_per_side = 2;
  options.noise_seed = 77;
  return options;
}

TEST(SimulatedSequenceTest, OneScanPerGroundTruthPoseAndOdometryStartsAtTheTruth) {
  const SimulatedSequence sequence = SimulateSequence(SmallBuilding());
  ASSERT_GT(sequence.scans.size(), 500u);
  ASSERT_EQ(sequence.scans.size(), sequence.ground_truth.size());
  ASSERT_EQ(sequence.odometry.size(), sequence.ground_truth.size());
  for (std::size_t i = 0; i < sequence.scans.size(); ++i) {
    EXPECT_EQ(sequence.scans[i].stamp_s, sequence.ground_truth.stamps_s()[i]);
    EXPECT_EQ(sequence.odometry.stamps_s()[i], sequence.ground_truth.stamps_s()[i]);
  }
  EXPECT_EQ(sequence.odometry.poses().front().position, sequence.ground_truth.poses().front().position);
  // Noisy odometry drifts away from the truth over a sequence of this length.
  EXPECT_GT((sequence.odometry.poses().back().position - sequence.ground_truth.poses().back().position).norm(), 1e-3);
  EXPECT_EQ(sequence.specification.at("generator"), "slamsweep.simulation");
  EXPECT_EQ(sequence.specification.at("noise_seed"), 77u);
  EXPECT_EQ(sequence.specification.at("scan_count"), sequence.scans.size());
  EXPECT_EQ(sequence.specification.at("floor_plan").at("rooms_per_side"), 2);
  EXPECT_GT(sequence.floor_plan.CellCount(), 0u);
}

TEST(SimulatedSequenceTest, WithoutNoiseScansMatchRayCastsFromTheTruth) {
  SimulationOptions options = SmallBuilding();
  options.range_noise = {};
  options.odometry_noise = {};
  const SimulatedSequence sequence = SimulateSequence(options);
  for (std::size_t i = 0; i < sequence.ground_truth.size(); ++i) {
    EXPECT_EQ(sequence.odometry.poses()[i].position, sequence.ground_truth.poses()[i].position);
  }
  for (std::size_t i = 0; i < sequence.scans.size(); i += 97) {
    const LaserScan& scan = sequence.scans[i];
    const Pose& pose = sequence.ground_truth.poses()[i];
    for (std::size_t b = 0; b < scan.BeamCount(); b += 7) {
      const double range = CastRay(sequence.floor_plan, pose.position.x(), pose.position.y(),
                                   pose.Yaw() + scan.BeamAngleRad(b), options.laser.range_max_m);
      if (range < 0.0) {
        EXPECT_FALSE(scan.IsHit(scan.ranges_m[b]));
      } else {
        EXPECT_NEAR(scan.ranges_m[b], range, 1e-5);
      }
    }
  }
}

TEST(SimulatedSequenceTest, SameOptionsSameSequenceOtherNoiseSeedOtherNoise) {
  const SimulatedSequence a = SimulateSequence(SmallBuilding());
  const SimulatedSequence b = SimulateSequence(SmallBuilding());
  SimulationOptions other = SmallBuilding();
  other.noise_seed = 78;
  const SimulatedSequence c = SimulateSequence(other);
  ASSERT_EQ(a.scans.size(), b.scans.size());
  for (std::size_t i = 0; i < a.scans.size(); ++i) ASSERT_EQ(a.scans[i].ranges_m, b.scans[i].ranges_m);
  for (std::size_t i = 0; i < a.odometry.size(); ++i)
    ASSERT_EQ(a.odometry.poses()[i].position, b.odometry.poses()[i].position);
  // A new noise seed changes the noise, not the building or the path.
  ASSERT_EQ(a.scans.size(), c.scans.size());
  EXPECT_EQ(a.floor_plan.cells, c.floor_plan.cells);
  EXPECT_EQ(a.ground_truth.poses().back().position, c.ground_truth.poses().back().position);
  EXPECT_NE(a.scans[10].ranges_m, c.scans[10].ranges_m);
  EXPECT_NE(a.odometry.poses().back().position, c.odometry.poses().back().position);
}

TEST(SimulatedSequenceTest, OptionsRoundTripThroughTheSpecification) {
  SimulationOptions options = SmallBuilding();
  options.laser.beam_count = 180;
  options.range_noise.dropout_probability = 0.02;
  options.odometry_noise.scale_error = 0.01;
  const nlohmann::json json = options;
  const SimulationOptions back = SimulationOptionsFromJson(json);
  EXPECT_EQ(back.floor_plan, options.floor_plan);
  EXPECT_EQ(back.path, options.path);
  EXPECT_EQ(back.laser, options.laser);
  EXPECT_EQ(back.range_noise, options.range_noise);
  EXPECT_EQ(back.odometry_noise, options.odometry_noise);
  EXPECT_EQ(back.noise_seed, 77u);

  nlohmann::json typo = json;
  typo["floor_plan"]["rooms"] = 3;
  EXPECT_THAT([&] { SimulationOptionsFromJson(typo); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("simulation.floor_plan.rooms: unknown option")));
  nlohmann::json future = json;
  future["version"] = 2;
  EXPECT_THAT([&] { SimulationOptionsFromJson(future); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("simulation.version")));
  nlohmann::json bad_noise = json;
  bad_noise["odometry_noise"]["alpha1"] = -1;
  EXPECT_THAT([&] { SimulationOptionsFromJson(bad_noise); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("simulation.odometry_noise.alpha1")));
}

TEST(SimulatedSequenceTest, InvalidOptionsAreInputErrors) {
  SimulationOptions options = SmallBuilding();
  options.range_noise.sigma_m = -1.0;
  EXPECT_THAT([&] { SimulateSequence(options); }, ::testing::ThrowsMessage<InputError>(HasSubstr("sigma_m")));
  options = SmallBuilding();
  options.path.rate_hz = 0.0;
  EXPECT_THAT([&] { SimulateSequence(options); }, ::testing::ThrowsMessage<InputError>(HasSubstr("rate_hz")));
}

}  // namespace
}  // namespace slamsweep::evaluator
