#include "evaluator/trajectory_metrics/alignment.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

constexpr double kTolerance = 1e-9;

// A spread of non-coplanar positions with varied orientations, stamped 0, 1, 2, ...
Trajectory Spread3d(int count) {
  Trajectory trajectory;
  for (int i = 0; i < count; ++i) {
    Pose pose;
    pose.position = Eigen::Vector3d(std::sin(0.7 * i) * 4.0, std::cos(0.3 * i) * 2.0 + 0.1 * i, std::sin(1.3 * i));
    pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.2 * i, Eigen::Vector3d(1, 2, 3).normalized()));
    trajectory.Add(i, pose);
  }
  return trajectory;
}

Trajectory Transformed(const Trajectory& trajectory, const Eigen::Matrix3d& rotation,
                       const Eigen::Vector3d& translation, double scale) {
  Trajectory out;
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    Pose pose = trajectory.poses()[i];
    pose.position = rotation * (scale * pose.position) + translation;
    pose.orientation = Eigen::Quaterniond(rotation) * pose.orientation;
    out.Add(trajectory.stamps_s()[i], pose);
  }
  return out;
}

Eigen::Matrix3d TiltedRotation() {
  return (Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-0.3, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()))
      .toRotationMatrix();
}

void ExpectSamePoses(const Trajectory& actual, const Trajectory& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    EXPECT_LT((actual.poses()[i].position - expected.poses()[i].position).norm(), kTolerance) << "pose " << i;
    EXPECT_LT(RotationAngleRad(actual.poses()[i].orientation.conjugate() * expected.poses()[i].orientation), kTolerance)
        << "pose " << i;
  }
}

TEST(AlignmentTest, ByIndicesEqualsTheAlignmentOfThePairedCopiesBitForBit) {
  // Pairs taken out of order, one pose twice: the fit through the indices reads the same poses in the same order
  // as the fit over copies of them, so every mode gives the very same doubles.
  const Trajectory estimate = Spread3d(50);
  const Trajectory reference = Transformed(estimate, TiltedRotation(), Eigen::Vector3d(1, 2, 3), 1.3);
  AssociatedIndices pairs;
  for (std::size_t k = 0; k < 40; ++k) {
    pairs.reference_ids.push_back((k * 7) % 50);
    pairs.estimate_ids.push_back(k == 5 ? 3 : (k * 7) % 50);
  }
  const Trajectory reference_copy = reference.Subset(pairs.reference_ids);
  const Trajectory estimate_copy = estimate.Subset(pairs.estimate_ids);
  for (AlignmentMode mode :
       {AlignmentMode::kOrigin, AlignmentMode::kSe2, AlignmentMode::kSe3, AlignmentMode::kSim2, AlignmentMode::kSim3}) {
    for (int n_to_align : {-1, 10}) {
      const AlignmentOptions options{mode, n_to_align};
      const Alignment by_indices = *ComputeAlignment(reference, estimate, pairs, options);
      const Alignment by_copies = *ComputeAlignment(reference_copy, estimate_copy, options);
      EXPECT_EQ(by_indices.rotation, by_copies.rotation) << AlignmentModeName(mode);
      EXPECT_EQ(by_indices.translation, by_copies.translation) << AlignmentModeName(mode);
      EXPECT_EQ(by_indices.scale, by_copies.scale) << AlignmentModeName(mode);
      EXPECT_EQ(by_indices.planar, by_copies.planar) << AlignmentModeName(mode);
    }
  }
  EXPECT_FALSE(ComputeAlignment(reference, estimate, pairs, AlignmentOptions{}).has_value());
}

TEST(AlignmentTest, Se3RecoversAKnownRigidTransform) {
  const Trajectory estimate = Spread3d(50);
  const Eigen::Vector3d translation(5.0, -3.0, 2.0);
  const Trajectory reference = Transformed(estimate, TiltedRotation(), translation, 1.0);
  const std::optional<Alignment> alignment =
      ComputeAlignment(reference, estimate, AlignmentOptions{AlignmentMode::kSe3, -1});
  ASSERT_TRUE(alignment.has_value());
  EXPECT_LT((alignment->rotation - TiltedRotation()).norm(), kTolerance);
  EXPECT_LT((alignment->translation - translation).norm(), kTolerance);
  EXPECT_EQ(alignment->scale, 1.0);
  ExpectSamePoses(ApplyAlignment(estimate, *alignment), reference);
}

TEST(AlignmentTest, Sim3RecoversAKnownScale) {
  const Trajectory estimate = Spread3d(50);
  const Trajectory reference = Transformed(estimate, TiltedRotation(), Eigen::Vector3d(1, 2, 3), 1.7);
  const std::optional<Alignment> alignment =
      ComputeAlignment(reference, estimate, AlignmentOptions{AlignmentMode::kSim3, -1});
  ASSERT_TRUE(alignment.has_value());
  EXPECT_NEAR(alignment->scale, 1.7, kTolerance);
  ExpectSamePoses(ApplyAlignment(estimate, *alignment), reference);
  // Without scale the fit cannot be exact.
  const std::optional<Alignment> rigid =
      ComputeAlignment(reference, estimate, AlignmentOptions{AlignmentMode::kSe3, -1});
  EXPECT_EQ(rigid->scale, 1.0);
}

TEST(AlignmentTest, Se2RecoversYawAndShiftAndLeavesZAlone) {
  // Planar motion with a z that the x-y fit must neither use nor change.
  Trajectory estimate;
  Trajectory reference;
  const double yaw = std::numbers::pi / 6.0;
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (int i = 0; i < 40; ++i) {
    Pose pose = Pose::Planar(std::cos(0.2 * i) * 3.0, 0.5 * i, 0.1 * i);
    pose.position.z() = 0.05 * i * i;
    estimate.Add(i, pose);
    Pose moved = pose;
    moved.position = rotation * pose.position + Eigen::Vector3d(5.0, -3.0, 0.0);
    moved.orientation = Eigen::Quaterniond(rotation) * pose.orientation;
    reference.Add(i, moved);
  }
  for (AlignmentMode mode : {AlignmentMode::kSe2, AlignmentMode::kSim2}) {
    const std::optional<Alignment> alignment = ComputeAlignment(reference, estimate, AlignmentOptions{mode, -1});
    ASSERT_TRUE(alignment.has_value());
    EXPECT_TRUE(alignment->planar);
    EXPECT_NEAR(std::atan2(alignment->rotation(1, 0), alignment->rotation(0, 0)), yaw, kTolerance);
    EXPECT_EQ(alignment->rotation(2, 2), 1.0);
    EXPECT_EQ(alignment->translation.z(), 0.0);
    EXPECT_NEAR(alignment->translation.x(), 5.0, kTolerance);
    EXPECT_NEAR(alignment->translation.y(), -3.0, kTolerance);
    EXPECT_NEAR(alignment->scale, 1.0, kTolerance);
    const Trajectory aligned = ApplyAlignment(estimate, *alignment);
    ExpectSamePoses(aligned, reference);
    for (std::size_t i = 0; i < aligned.size(); ++i) {
      EXPECT_EQ(aligned.poses()[i].position.z(), estimate.poses()[i].position.z());
    }
  }
}

TEST(AlignmentTest, Sim2ScalesXAndYOnly) {
  Trajectory estimate;
  Trajectory reference;
  for (int i = 0; i < 30; ++i) {
    Pose pose = Pose::Planar(std::sin(0.3 * i), 0.2 * i, 0.0);
    pose.position.z() = 1.0 + i;
    estimate.Add(i, pose);
    Pose scaled = pose;
    scaled.position.head<2>() *= 2.5;
    reference.Add(i, scaled);
  }
  const Alignment alignment = *ComputeAlignment(reference, estimate, AlignmentOptions{AlignmentMode::kSim2, -1});
  EXPECT_NEAR(alignment.scale, 2.5, kTolerance);
  const Eigen::Vector3d moved = alignment.Apply(Eigen::Vector3d(1.0, 2.0, 7.0));
  EXPECT_NEAR(moved.x(), 2.5, kTolerance);
  EXPECT_NEAR(moved.y(), 5.0, kTolerance);
  EXPECT_EQ(moved.z(), 7.0);
}

TEST(AlignmentTest, OriginMovesTheFirstPoseOntoTheReference) {
  const Trajectory estimate = Spread3d(10);
  const Trajectory reference = Transformed(Spread3d(10), TiltedRotation(), Eigen::Vector3d(1, 1, 1), 1.0);
  const Alignment alignment = *ComputeAlignment(reference, estimate, AlignmentOptions{AlignmentMode::kOrigin, -1});
  const Pose moved = alignment.Apply(estimate.poses()[0]);
  EXPECT_LT((moved.position - reference.poses()[0].position).norm(), kTolerance);
  EXPECT_LT(RotationAngleRad(moved.orientation.conjugate() * reference.poses()[0].orientation), kTolerance);
  // Here the whole trajectory differs by one rigid transform, so origin alignment recovers it all.
  ExpectSamePoses(ApplyAlignment(estimate, alignment), reference);
}

TEST(AlignmentTest, NToAlignFitsOnTheFirstPairsOnly) {
  const Trajectory estimate = Spread3d(40);
  Trajectory reference = Transformed(estimate, TiltedRotation(), Eigen::Vector3d(2, 0, 0), 1.0);
  // Corrupt every pose after the first 10: only a fit on those 10 can recover the transform.
  for (std::size_t i = 10; i < reference.size(); ++i) reference.mutable_poses()[i].position += Eigen::Vector3d(0, 7, 0);
  const Alignment first10 = *ComputeAlignment(reference, estimate, AlignmentOptions{AlignmentMode::kSe3, 10});
  EXPECT_LT((first10.rotation - TiltedRotation()).norm(), kTolerance);
  EXPECT_LT((first10.translation - Eigen::Vector3d(2, 0, 0)).norm(), kTolerance);
  const Alignment all = *ComputeAlignment(reference, estimate, AlignmentOptions{AlignmentMode::kSe3, -1});
  EXPECT_GT((all.translation - Eigen::Vector3d(2, 0, 0)).norm(), 1.0);
  // More than there are pairs means all of them, as evo's slicing does.
  const Alignment many = *ComputeAlignment(reference, estimate, AlignmentOptions{AlignmentMode::kSe3, 1000});
  EXPECT_LT((many.translation - all.translation).norm(), kTolerance);
}

TEST(AlignmentTest, AMirroredConfigurationStillGivesARotation) {
  const Trajectory estimate = Spread3d(30);
  Trajectory reference = estimate;
  for (Pose& pose : reference.mutable_poses()) pose.position.z() = -pose.position.z();
  const Alignment alignment = *ComputeAlignment(reference, estimate, AlignmentOptions{AlignmentMode::kSe3, -1});
  EXPECT_NEAR(alignment.rotation.determinant(), 1.0, kTolerance);
  EXPECT_LT((alignment.rotation * alignment.rotation.transpose() - Eigen::Matrix3d::Identity()).norm(), kTolerance);
}

TEST(AlignmentTest, DegenerateConfigurationsAreInputErrors) {
  Trajectory line;
  for (int i = 0; i < 10; ++i) line.Add(i, Pose::Planar(i, 2.0 * i, 0.0));
  try {
    ComputeAlignment(line, line, AlignmentOptions{AlignmentMode::kSe3, -1});
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("degenerate"));
  }
  // In the plane a line still fixes the rotation (rank 1 = dim - 1).
  EXPECT_NO_THROW(ComputeAlignment(line, line, AlignmentOptions{AlignmentMode::kSe2, -1}));
  Trajectory point;
  point.Add(0.0, Pose::Planar(1.0, 1.0, 0.0));
  EXPECT_THROW(ComputeAlignment(point, point, AlignmentOptions{AlignmentMode::kSe2, -1}), InputError);
  EXPECT_THROW(ComputeAlignment(line, point, AlignmentOptions{AlignmentMode::kSe3, -1}), InputError);
  EXPECT_THROW(ComputeAlignment(Trajectory(), Trajectory(), AlignmentOptions{AlignmentMode::kOrigin, -1}), InputError);
  EXPECT_FALSE(ComputeAlignment(Trajectory(), Trajectory(), AlignmentOptions{}).has_value());
}

TEST(AlignmentTest, ModeNamesRoundTripAndBadOnesListTheChoices) {
  for (AlignmentMode mode : {AlignmentMode::kNone, AlignmentMode::kOrigin, AlignmentMode::kSe2, AlignmentMode::kSe3,
                             AlignmentMode::kSim2, AlignmentMode::kSim3}) {
    EXPECT_EQ(ParseAlignmentMode(AlignmentModeName(mode)), mode);
  }
  try {
    ParseAlignmentMode("SE3");
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("none, origin, se2, se3, sim2, sim3"));
    EXPECT_THAT(error.what(), HasSubstr("'SE3'"));
  }
  EXPECT_THROW(ValidateAlignmentOptions(AlignmentOptions{AlignmentMode::kSe3, 0}), InputError);
  EXPECT_THROW(ValidateAlignmentOptions(AlignmentOptions{AlignmentMode::kSe3, -2}), InputError);
}

TEST(AlignmentTest, JsonCarriesScaleRotationAndTranslation) {
  Alignment alignment;
  alignment.scale = 2.0;
  alignment.translation = Eigen::Vector3d(1, 2, 3);
  const nlohmann::json json = ToJson(alignment);
  EXPECT_EQ(json.at("scale"), 2.0);
  EXPECT_EQ(json.at("translation"), nlohmann::json({1.0, 2.0, 3.0}));
  EXPECT_EQ(json.at("rotation"), nlohmann::json({{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}));
}

}  // namespace
}  // namespace slamsweep::evaluator
