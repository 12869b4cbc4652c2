#include "evaluator/trajectory_metrics/association.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// Each pose carries its own index in x, so the pairing can be read back from the result.
Trajectory Indexed(const std::vector<double>& stamps_s) {
  Trajectory trajectory;
  for (std::size_t i = 0; i < stamps_s.size(); ++i) {
    trajectory.Add(stamps_s[i], Pose::Planar(static_cast<double>(i), 0.0, 0.0));
  }
  return trajectory;
}

std::vector<int> Indices(const Trajectory& trajectory) {
  std::vector<int> indices;
  for (const Pose& pose : trajectory.poses()) indices.push_back(static_cast<int>(pose.position.x()));
  return indices;
}

TEST(AssociationTest, IteratesTheReferenceWhenTheEstimateIsLonger) {
  const Trajectory reference = Indexed({0.0, 1.0, 2.0});
  const Trajectory estimate = Indexed({0.0, 0.004, 1.003, 2.0, 2.002, 3.0});
  const Association association = Associate(reference, estimate, AssociationOptions{});
  EXPECT_THAT(Indices(association.reference), ElementsAre(0, 1, 2));
  EXPECT_THAT(Indices(association.estimate), ElementsAre(0, 2, 3));
  EXPECT_EQ(association.reference_unpaired, 0u);
  EXPECT_EQ(association.estimate_unpaired, 3u);
  // The pairs keep their own, unshifted stamps.
  EXPECT_DOUBLE_EQ(association.estimate.stamps_s()[1], 1.003);
}

TEST(AssociationTest, LongerTrajectoryPosesCanBePairedTwice) {
  // The estimate is shorter, so it is iterated; both of its first poses are nearest reference pose 1.
  const Trajectory reference = Indexed({0.0, 1.0, 2.0, 3.0});
  const Trajectory estimate = Indexed({0.999, 1.001, 5.0});
  const Association association = Associate(reference, estimate, AssociationOptions{});
  EXPECT_THAT(Indices(association.reference), ElementsAre(1, 1));
  EXPECT_THAT(Indices(association.estimate), ElementsAre(0, 1));
  EXPECT_EQ(association.reference_unpaired, 3u);
  EXPECT_EQ(association.estimate_unpaired, 1u);
}

TEST(AssociationTest, EqualSizesIterateTheEstimate) {
  // With equal sizes evo iterates its second trajectory (the estimate): estimate pose 1 pairs
  // with reference pose 0 again; iterating the reference would have paired reference pose 1 too.
  const Trajectory reference = Indexed({0.0, 1.0});
  const Trajectory estimate = Indexed({0.0, 0.005});
  const Association association = Associate(reference, estimate, AssociationOptions{});
  EXPECT_THAT(Indices(association.reference), ElementsAre(0, 0));
  EXPECT_THAT(Indices(association.estimate), ElementsAre(0, 1));
}

TEST(AssociationTest, TiesGoToTheLowestIndexAsNumpyArgmin) {
  AssociationOptions options;
  options.t_max_diff_s = 0.5;
  // 1.0 is exactly 0.5 s from both 0.5 and 1.5.
  EXPECT_THAT(Indices(Associate(Indexed({0.5, 1.5, 9.0}), Indexed({1.0}), options).reference), ElementsAre(0));
  // Unsorted: the lowest index wins, not the lowest stamp.
  EXPECT_THAT(Indices(Associate(Indexed({1.5, 0.5, 9.0}), Indexed({1.0}), options).reference), ElementsAre(0));
  EXPECT_THAT(Indices(Associate(Indexed({9.0, 1.5, 0.5}), Indexed({1.0}), options).reference), ElementsAre(1));
  // Repeated stamps: the first of them.
  EXPECT_THAT(Indices(Associate(Indexed({0.0, 2.0, 2.0, 2.0}), Indexed({2.0}), options).reference), ElementsAre(1));
}

TEST(AssociationTest, OffsetIsAddedToTheEstimateStamps) {
  // The estimate's clock runs 100 s behind the reference's: t_offset = +100 s fixes it, whichever
  // trajectory is the longer one.
  AssociationOptions options;
  options.t_offset_s = 100.0;
  const Association estimate_longer = Associate(Indexed({100.0, 101.0}), Indexed({0.0, 0.5, 1.0, 1.5}), options);
  EXPECT_THAT(Indices(estimate_longer.estimate), ElementsAre(0, 2));
  const Association reference_longer = Associate(Indexed({100.0, 100.5, 101.0, 101.5}), Indexed({0.0, 1.0}), options);
  EXPECT_THAT(Indices(reference_longer.reference), ElementsAre(0, 2));

  options.t_offset_s = -100.0;
  EXPECT_THROW(Associate(Indexed({100.0, 101.0}), Indexed({0.0, 0.5, 1.0, 1.5}), options), InputError);
}

TEST(AssociationTest, ToleranceIsInclusive) {
  AssociationOptions options;
  options.t_max_diff_s = 0.25;
  EXPECT_EQ(Associate(Indexed({0.0, 5.0}), Indexed({0.25}), options).estimate.size(), 1u);
  options.t_max_diff_s = 0.125;
  EXPECT_THROW(Associate(Indexed({0.0, 5.0}), Indexed({0.25}), options), InputError);
}

TEST(AssociationTest, NoPairsNamesBothTimeRangesAndWhatToTry) {
  const Trajectory reference = Indexed({10.0, 11.0, 12.0});
  const Trajectory estimate = Indexed({20.0, 21.0});
  try {
    Associate(reference, estimate, AssociationOptions{});
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr(DescribeTimeRange(reference)));
    EXPECT_THAT(error.what(), HasSubstr(DescribeTimeRange(estimate)));
    EXPECT_THAT(error.what(), HasSubstr("--t-max-diff"));
    EXPECT_THAT(error.what(), HasSubstr("--t-offset"));
  }
}

TEST(AssociationTest, EmptyTrajectoriesAndBadOptionsAreInputErrors) {
  EXPECT_THROW(Associate(Trajectory(), Indexed({0.0}), AssociationOptions{}), InputError);
  EXPECT_THROW(Associate(Indexed({0.0}), Trajectory(), AssociationOptions{}), InputError);
  AssociationOptions negative;
  negative.t_max_diff_s = -0.1;
  try {
    Associate(Indexed({0.0}), Indexed({0.0}), negative);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("t_max_diff"));
  }
  AssociationOptions not_a_number;
  not_a_number.t_offset_s = std::nan("");
  EXPECT_THROW(ValidateAssociationOptions(not_a_number), InputError);
}

// evo's association written out the slow, obvious way: the independent oracle for the fast one.
struct OraclePairs {
  std::vector<int> reference;
  std::vector<int> estimate;
};

OraclePairs EvoOracle(const std::vector<double>& reference_s, const std::vector<double>& estimate_s, double max_diff_s,
                      double offset_s) {
  const bool estimate_longer = estimate_s.size() > reference_s.size();
  const std::vector<double>& shorter = estimate_longer ? reference_s : estimate_s;
  std::vector<double> longer = estimate_longer ? estimate_s : reference_s;
  for (double& stamp : longer) stamp += estimate_longer ? offset_s : -offset_s;
  OraclePairs pairs;
  for (std::size_t i = 0; i < shorter.size(); ++i) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < longer.size(); ++k) {
      if (std::abs(longer[k] - shorter[i]) < std::abs(longer[best] - shorter[i])) best = k;
    }
    if (std::abs(longer[best] - shorter[i]) > max_diff_s) continue;
    (estimate_longer ? pairs.reference : pairs.estimate).push_back(static_cast<int>(i));
    (estimate_longer ? pairs.estimate : pairs.reference).push_back(static_cast<int>(best));
  }
  return pairs;
}

TEST(AssociationTest, MatchesTheQuadraticOracleOnRandomUnsortedStamps) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> size(1, 40);
  std::uniform_int_distribution<int> tick(0, 60);
  std::uniform_int_distribution<int> sorted(0, 2);
  int compared = 0;
  for (int round = 0; round < 500; ++round) {
    // Stamps on a 0.05 s grid collide and tie often; some rounds sort them, most do not.
    std::vector<double> reference_s(static_cast<std::size_t>(size(random)));
    std::vector<double> estimate_s(static_cast<std::size_t>(size(random)));
    for (double& s : reference_s) s = 0.05 * tick(random);
    for (double& s : estimate_s) s = 0.05 * tick(random);
    if (sorted(random) == 0) {
      std::sort(reference_s.begin(), reference_s.end());
      std::sort(estimate_s.begin(), estimate_s.end());
    }
    AssociationOptions options;
    options.t_max_diff_s = 0.05 * (round % 3);
    options.t_offset_s = 0.05 * (round % 5 - 2);
    const OraclePairs expected = EvoOracle(reference_s, estimate_s, options.t_max_diff_s, options.t_offset_s);
    if (expected.reference.empty()) {
      EXPECT_THROW(Associate(Indexed(reference_s), Indexed(estimate_s), options), InputError);
      continue;
    }
    const Association association = Associate(Indexed(reference_s), Indexed(estimate_s), options);
    ASSERT_EQ(Indices(association.reference), expected.reference) << "round " << round;
    ASSERT_EQ(Indices(association.estimate), expected.estimate) << "round " << round;
    // Giving the trajectories up (the poses stay in place) pairs the same poses with the same counts.
    const Trajectory reference = Indexed(reference_s);
    const Trajectory estimate = Indexed(estimate_s);
    const Association kept = Associate(Trajectory(reference), Trajectory(estimate), options);
    ASSERT_EQ(Indices(kept.reference), expected.reference) << "round " << round;
    ASSERT_EQ(Indices(kept.estimate), expected.estimate) << "round " << round;
    EXPECT_EQ(kept.reference.stamps_s(), association.reference.stamps_s());
    EXPECT_EQ(kept.reference_unpaired, association.reference_unpaired);
    EXPECT_EQ(kept.estimate_unpaired, association.estimate_unpaired);
    ++compared;
  }
  EXPECT_GT(compared, 200);
}

TEST(AssociationTest, IndicesNameThePosesAssociateCopies) {
  // Estimate longer, poses paired twice, unsorted stamps and an offset: the indices give Associate's pairs.
  const std::vector<std::pair<std::vector<double>, std::vector<double>>> cases = {
      {{0.0, 1.0, 2.0}, {0.0, 0.004, 1.003, 2.0, 2.002, 3.0}},
      {{0.0, 1.0, 2.0, 3.0}, {0.999, 1.001, 5.0}},
      {{2.0, 0.0, 1.0, 3.0}, {1.001, 0.0, 2.999}},
      {{100.0, 101.0, 102.0}, {0.0, 1.0, 2.0, 3.0}},
  };
  for (const auto& [reference_stamps, estimate_stamps] : cases) {
    const Trajectory reference = Indexed(reference_stamps);
    const Trajectory estimate = Indexed(estimate_stamps);
    AssociationOptions options;
    options.t_offset_s = reference_stamps[0] == 100.0 ? 100.0 : 0.0;
    const Association copied = Associate(reference, estimate, options);
    const AssociatedIndices indices = AssociateIndices(reference, estimate, options);
    ASSERT_EQ(indices.size(), copied.reference.size());
    std::vector<int> reference_ids(indices.reference_ids.begin(), indices.reference_ids.end());
    std::vector<int> estimate_ids(indices.estimate_ids.begin(), indices.estimate_ids.end());
    EXPECT_EQ(reference_ids, Indices(copied.reference));
    EXPECT_EQ(estimate_ids, Indices(copied.estimate));
    EXPECT_EQ(indices.reference_unpaired, copied.reference_unpaired);
    EXPECT_EQ(indices.estimate_unpaired, copied.estimate_unpaired);
  }
}

TEST(AssociationTest, PairedSideIsTheInputWhenEveryPoseIsPairedInOrder) {
  const Trajectory trajectory = Indexed({0.0, 1.0, 2.0});
  const std::vector<std::size_t> all = {0, 1, 2};
  EXPECT_EQ(&PairedSide(trajectory, all).trajectory(), &trajectory);
  // Fewer, repeated or reordered poses: a copy of just the paired ones, in pair order.
  for (const std::vector<std::size_t>& ids :
       {std::vector<std::size_t>{0, 2}, std::vector<std::size_t>{0, 1, 1}, std::vector<std::size_t>{1, 0, 2}}) {
    const PairedSide side(trajectory, ids);
    EXPECT_NE(&side.trajectory(), &trajectory);
    EXPECT_EQ(Indices(side.trajectory()), std::vector<int>(ids.begin(), ids.end()));
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
