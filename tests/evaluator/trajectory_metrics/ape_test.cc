#include "evaluator/trajectory_metrics/ape.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

// A planar loop at 10 Hz with varying heading.
Trajectory Loop(int count) {
  Trajectory trajectory;
  for (int i = 0; i < count; ++i) {
    const double t = 0.1 * i;
    trajectory.Add(t, Pose::Planar(3.0 * std::cos(0.2 * t), 2.0 * std::sin(0.3 * t), 0.25 * t));
  }
  return trajectory;
}

ApeOptions Options(PoseRelation relation, AlignmentMode mode) {
  ApeOptions options;
  options.pose_relation = relation;
  options.alignment.mode = mode;
  return options;
}

TEST(ApeTest, IdenticalTrajectoriesGiveZeroErrorUnderEveryAlignment) {
  const Trajectory trajectory = Loop(100);
  for (PoseRelation relation : {PoseRelation::kTranslation, PoseRelation::kRotationDeg}) {
    for (AlignmentMode mode :
         {AlignmentMode::kNone, AlignmentMode::kOrigin, AlignmentMode::kSe2, AlignmentMode::kSim2}) {
      const MetricResult result = Ape(Options(relation, mode)).Compute(trajectory, trajectory);
      EXPECT_EQ(result.statistics.n, 100u);
      EXPECT_LT(result.statistics.max, 1e-9) << AlignmentModeName(mode);
      EXPECT_EQ(result.pairs, 100u);
      EXPECT_EQ(result.reference_unpaired, 0u);
      EXPECT_EQ(result.estimate_unpaired, 0u);
    }
  }
}

TEST(ApeTest, AShiftedEstimateHasTheShiftAsErrorUnlessAligned) {
  const Trajectory reference = Loop(50);
  Trajectory estimate = reference;
  for (Pose& pose : estimate.mutable_poses()) pose.position += Eigen::Vector3d(3.0, 4.0, 0.0);
  const MetricResult raw = Ape(Options(PoseRelation::kTranslation, AlignmentMode::kNone)).Compute(reference, estimate);
  EXPECT_NEAR(raw.statistics.rmse, 5.0, 1e-12);
  EXPECT_NEAR(raw.statistics.min, 5.0, 1e-12);
  EXPECT_NEAR(raw.statistics.max, 5.0, 1e-12);
  EXPECT_NEAR(raw.statistics.sse, 50 * 25.0, 1e-9);
  EXPECT_FALSE(raw.alignment.has_value());
  const MetricResult aligned =
      Ape(Options(PoseRelation::kTranslation, AlignmentMode::kSe2)).Compute(reference, estimate);
  EXPECT_LT(aligned.statistics.max, 1e-9);
  ASSERT_TRUE(aligned.alignment.has_value());
  EXPECT_NEAR(aligned.alignment->translation.x(), -3.0, 1e-9);
  EXPECT_NEAR(aligned.alignment->translation.y(), -4.0, 1e-9);
}

TEST(ApeTest, RotationErrorIsTheRelativeAngleInDegrees) {
  const Trajectory reference = Loop(20);
  Trajectory estimate = reference;
  const Eigen::Quaterniond tilt(Eigen::AngleAxisd(DegToRad(10.0), Eigen::Vector3d::UnitX()));
  for (Pose& pose : estimate.mutable_poses()) pose.orientation = pose.orientation * tilt;
  const MetricResult result =
      Ape(Options(PoseRelation::kRotationDeg, AlignmentMode::kNone)).Compute(reference, estimate);
  EXPECT_EQ(result.unit, "deg");
  EXPECT_NEAR(result.statistics.min, 10.0, 1e-9);
  EXPECT_NEAR(result.statistics.max, 10.0, 1e-9);
}

TEST(ApeTest, UnpairedPosesAreCounted) {
  const Trajectory reference = Loop(30);
  // The estimate covers only stamps 1.0 .. 1.9 (10 poses).
  Trajectory estimate;
  for (std::size_t i = 10; i < 20; ++i) estimate.Add(reference.stamps_s()[i], reference.poses()[i]);
  const MetricResult result = Ape(ApeOptions{}).Compute(reference, estimate);
  EXPECT_EQ(result.pairs, 10u);
  EXPECT_EQ(result.reference_unpaired, 20u);
  EXPECT_EQ(result.estimate_unpaired, 0u);
}

TEST(ApeTest, JsonHasStatisticsAtTopLevelAndTheFullSpecification) {
  ApeOptions options = Options(PoseRelation::kTranslation, AlignmentMode::kSe3);
  options.association.t_max_diff_s = 0.02;
  options.association.t_offset_s = 0.5;
  options.alignment.n_to_align = 25;
  Trajectory reference = Loop(60);
  for (Pose& pose : reference.mutable_poses()) pose.position.z() = std::sin(pose.position.x());
  const Trajectory estimate = reference.Shifted(-0.5);
  const nlohmann::json json = Ape(options).Compute(reference, estimate).ToJson();
  for (const char* key : {"rmse", "mean", "median", "std", "min", "max", "sse", "n", "metric", "unit", "specification",
                          "pairs", "reference_unpaired", "estimate_unpaired", "alignment"}) {
    EXPECT_TRUE(json.contains(key)) << key;
  }
  EXPECT_FALSE(json.contains("errors"));
  EXPECT_EQ(json.at("metric"), "ape");
  EXPECT_EQ(json.at("unit"), "m");
  EXPECT_EQ(json.at("n"), 60);
  const nlohmann::json& specification = json.at("specification");
  EXPECT_EQ(specification.at("pose_relation"), "trans");
  EXPECT_EQ(specification.at("alignment"), "se3");
  EXPECT_EQ(specification.at("n_to_align"), 25);
  EXPECT_EQ(specification.at("t_max_diff_s"), 0.02);
  EXPECT_EQ(specification.at("t_offset_s"), 0.5);
  EXPECT_TRUE(json.at("alignment").contains("scale"));

  const nlohmann::json unaligned = Ape(ApeOptions{}).Compute(reference, reference).ToJson();
  EXPECT_FALSE(unaligned.contains("alignment"));
}

TEST(ApeTest, BadOptionsFailAtConstruction) {
  ApeOptions options;
  options.alignment.n_to_align = 0;
  EXPECT_THROW(Ape{options}, InputError);
  options = ApeOptions{};
  options.association.t_max_diff_s = -1.0;
  EXPECT_THROW(Ape{options}, InputError);
}

TEST(ApeTest, PoseRelationNamesRoundTripAndBadOnesListTheChoices) {
  EXPECT_EQ(ParsePoseRelation("trans"), PoseRelation::kTranslation);
  EXPECT_EQ(ParsePoseRelation("rot-deg"), PoseRelation::kRotationDeg);
  for (PoseRelation relation : {PoseRelation::kTranslation, PoseRelation::kRotationDeg}) {
    EXPECT_EQ(ParsePoseRelation(PoseRelationName(relation)), relation);
  }
  try {
    ParsePoseRelation("angle_deg");
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("trans, rot-deg"));
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
