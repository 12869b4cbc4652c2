#include "report/images/overlay_alignment.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "evaluator/core/input_error.h"

namespace slamsweep::report {
namespace {

using evaluator::Alignment;
using evaluator::Pose;
using evaluator::Trajectory;

TEST(InverseAlignmentTest, UndoesAPlanarSimilarity) {
  Alignment a;
  a.planar = true;
  a.scale = 2.5;
  a.rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  a.translation = {1.0, -3.0, 0.5};
  const Eigen::Vector3d p(0.3, 4.0, 1.2);
  const Eigen::Vector3d back = InverseAlignment(a).Apply(a.Apply(p));
  EXPECT_NEAR((back - p).norm(), 0.0, 1e-12);
}

TEST(InverseAlignmentTest, UndoesASpatialSimilarity) {
  Alignment a;
  a.scale = 0.8;
  a.rotation = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  a.translation = {1.0, 2.0, 3.0};
  const Eigen::Vector3d p(-2.0, 0.5, 7.0);
  EXPECT_NEAR((InverseAlignment(a).Apply(a.Apply(p)) - p).norm(), 0.0, 1e-12);
}

Trajectory Square() {
  Trajectory t;
  for (int i = 0; i < 40; ++i) {
    const double s = i / 10.0;
    const double x = i < 10 ? s : i < 20 ? 1.0 : i < 30 ? 3.0 - s : 0.0;
    const double y = i < 10 ? 0.0 : i < 20 ? s - 1.0 : i < 30 ? 1.0 : 4.0 - s;
    t.Add(i * 0.1, Pose::Planar(x, y, 0.0));
  }
  return t;
}

TEST(AlignReferenceOntoEstimateTest, RigidlyMovedReferenceLandsOnTheEstimate) {
  const Trajectory estimate = Square();
  // The reference is the estimate seen from another frame: rotated 30 degrees and shifted.
  const Pose frame = Pose::Planar(5.0, -2.0, std::numbers::pi / 6);
  Trajectory reference;
  for (std::size_t i = 0; i < estimate.size(); ++i) reference.Add(estimate.stamps_s()[i], frame * estimate.poses()[i]);
  const ReferenceInMapFrame placed = AlignReferenceOntoEstimate(reference, estimate, "se2", 0.01);
  ASSERT_TRUE(placed.reference.has_value()) << placed.note;
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    EXPECT_NEAR((placed.reference->poses()[i].position - estimate.poses()[i].position).norm(), 0.0, 1e-9);
  }
  EXPECT_THAT(placed.note, ::testing::HasSubstr("se2, 40 pairs"));
}

TEST(AlignReferenceOntoEstimateTest, NoneKeepsTheReference) {
  const Trajectory estimate = Square();
  const ReferenceInMapFrame placed = AlignReferenceOntoEstimate(estimate.Shifted(0.0), estimate, "none", 0.01);
  ASSERT_TRUE(placed.reference.has_value());
  EXPECT_EQ(placed.reference->poses()[5].position, estimate.poses()[5].position);
}

TEST(AlignReferenceOntoEstimateTest, NoCommonStampsIsANoteNotAnError) {
  const Trajectory estimate = Square();
  const ReferenceInMapFrame placed = AlignReferenceOntoEstimate(estimate.Shifted(100.0), estimate, "se2", 0.01);
  EXPECT_FALSE(placed.reference.has_value());
  EXPECT_THAT(placed.note, ::testing::HasSubstr("reference not shown"));
}

TEST(AlignReferenceOntoEstimateTest, UnknownAlignmentIsAnInputError) {
  const Trajectory estimate = Square();
  EXPECT_THROW(AlignReferenceOntoEstimate(estimate, estimate, "se4", 0.01), evaluator::InputError);
}

}  // namespace
}  // namespace slamsweep::report
