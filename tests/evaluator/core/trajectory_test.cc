#include "evaluator/core/trajectory.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

TEST(TrajectoryTest, RejectsNanPoseWithItsIndex) {
  Trajectory trajectory;
  trajectory.Add(0.0, Pose::Planar(0, 0, 0));
  Pose bad = Pose::Planar(0, 0, 0);
  bad.position.y() = std::nan("");
  try {
    trajectory.Add(0.1, bad);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("pose 1"));
  }
  EXPECT_EQ(trajectory.size(), 1u);
}

TEST(TrajectoryTest, MismatchedSizesAreRejected) { EXPECT_THROW(Trajectory({0.0, 1.0}, {Pose()}), InputError); }

TEST(TrajectoryTest, SubsetShiftAndPlanarity) {
  Trajectory trajectory({0.0, 1.0, 2.0}, {Pose::Planar(0, 0, 0), Pose::Planar(1, 0, 0.1), Pose::Planar(2, 0, 0.2)});
  EXPECT_TRUE(trajectory.IsPlanar());
  const std::vector<std::size_t> picked = {2, 0};
  const Trajectory subset = trajectory.Subset(picked);
  ASSERT_EQ(subset.size(), 2u);
  EXPECT_DOUBLE_EQ(subset.stamps_s()[0], 2.0);
  EXPECT_DOUBLE_EQ(subset.poses()[1].position.x(), 0.0);
  EXPECT_DOUBLE_EQ(trajectory.Shifted(0.5).StartS(), 0.5);
  trajectory.mutable_poses()[1].position.z() = 0.3;
  EXPECT_FALSE(trajectory.IsPlanar());
}

TEST(TrajectoryTest, SelectMovesIncreasingIndicesDownInPlaceAndCopiesOtherwise) {
  Trajectory trajectory;
  for (int i = 0; i < 6; ++i) trajectory.Add(10.0 + i, Pose::Planar(i, 0, 0));
  const std::vector<std::size_t> increasing = {1, 2, 4, 5};
  const Trajectory expected = trajectory.Subset(increasing);
  const Pose* storage = trajectory.poses().data();
  const Trajectory selected = std::move(trajectory).Select(increasing);
  EXPECT_EQ(selected.poses().data(), storage);  // no new memory
  EXPECT_EQ(selected.stamps_s(), expected.stamps_s());
  ASSERT_EQ(selected.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(selected.poses()[k].position, expected.poses()[k].position);

  Trajectory again;
  for (int i = 0; i < 3; ++i) again.Add(i, Pose::Planar(i, 0, 0));
  const std::vector<std::size_t> repeated = {1, 1, 0};
  const Trajectory copied = std::move(again).Select(repeated);
  EXPECT_EQ(copied.stamps_s(), (std::vector<double>{1.0, 1.0, 0.0}));
  const std::vector<std::size_t> outside = {0, 7};
  EXPECT_THROW(Trajectory(copied).Select(outside), std::out_of_range);
}

TEST(TrajectoryTest, EmptyTrajectoryHasNoTimeRange) {
  EXPECT_THROW(Trajectory().StartS(), InputError);
  EXPECT_EQ(DescribeTimeRange(Trajectory()), "no poses");
}

}  // namespace
}  // namespace slamsweep::evaluator
