#include "evaluator/trajectory_metrics/rpe.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

// Pairs as (first, second) so they print and compare readably.
std::vector<std::pair<std::size_t, std::size_t>> AsPairs(const std::vector<IndexPair>& pairs) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (const IndexPair& pair : pairs) out.emplace_back(pair.first, pair.second);
  return out;
}

using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

Trajectory AlongX(const std::vector<double>& xs_m, double period_s = 1.0) {
  Trajectory trajectory;
  for (std::size_t i = 0; i < xs_m.size(); ++i) trajectory.Add(period_s * i, Pose::Planar(xs_m[i], 0.0, 0.0));
  return trajectory;
}

Trajectory Turning(const std::vector<double>& yaws_deg) {
  Trajectory trajectory;
  for (std::size_t i = 0; i < yaws_deg.size(); ++i) trajectory.Add(i, Pose::Planar(0.0, 0.0, DegToRad(yaws_deg[i])));
  return trajectory;
}

PairSelectionOptions Selection(double delta, DeltaUnit unit, bool all_pairs, double tolerance = 0.1) {
  return PairSelectionOptions{delta, unit, all_pairs, tolerance};
}

TEST(PairSelectionTest, FramesConsecutiveAndAllPairs) {
  const Trajectory trajectory = AlongX({0, 1, 2, 3, 4, 5, 6});
  EXPECT_EQ(AsPairs(SelectPairs(trajectory, Selection(3, DeltaUnit::kFrames, false))), (Pairs{{0, 3}, {3, 6}}));
  EXPECT_EQ(AsPairs(SelectPairs(trajectory, Selection(5, DeltaUnit::kFrames, true))), (Pairs{{0, 5}, {1, 6}}));
  EXPECT_EQ(AsPairs(SelectPairs(trajectory, Selection(1, DeltaUnit::kFrames, false))).size(), 6u);
}

TEST(PairSelectionTest, MetresConsecutiveStartWhereThePathFirstReachesDelta) {
  // Steps of 0.4 m: the path reaches 1 m at pose 3 (1.2 m), then again 3 poses later.
  const Trajectory trajectory = AlongX({0, 0.4, 0.8, 1.2, 1.6, 2.0, 2.4, 2.8});
  EXPECT_EQ(AsPairs(SelectPairs(trajectory, Selection(1.0, DeltaUnit::kMeters, false))), (Pairs{{3, 6}}));
}

TEST(PairSelectionTest, MetresAllPairsTakeTheNearestWithinTolerance) {
  // Steps of 0.25 m: pose i + 4 is exactly 1 m on; from i = 6 on, the rest of the path is too short.
  const Trajectory trajectory = AlongX({0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.25});
  EXPECT_EQ(AsPairs(SelectPairs(trajectory, Selection(1.0, DeltaUnit::kMeters, true))),
            (Pairs{{0, 4}, {1, 5}, {2, 6}, {3, 7}, {4, 8}, {5, 9}}));
}

TEST(PairSelectionTest, MetresAllPairsBreakTiesTowardsTheLowerIndex) {
  // Steps of 0.5 m and delta 0.75 m: 0.5 and 1.0 m are equally near; the first one wins.
  const Trajectory even = AlongX({0, 0.5, 1.0});
  EXPECT_EQ(AsPairs(SelectPairs(even, Selection(0.75, DeltaUnit::kMeters, true, 1.0))), (Pairs{{0, 1}, {1, 2}}));
  // Standing still: poses 1, 2 and 3 are all 1 m from pose 0; pose 1 wins. From pose 1 the
  // nearest to 1 m is pose 4; from poses 2 and 3 too.
  const Trajectory pause = AlongX({0, 1, 1, 1, 2});
  EXPECT_EQ(AsPairs(SelectPairs(pause, Selection(1.0, DeltaUnit::kMeters, true))),
            (Pairs{{0, 1}, {1, 4}, {2, 4}, {3, 4}}));
}

TEST(PairSelectionTest, DegreesConsecutiveSumTheTurn) {
  // 31 degrees per pose: 90 degrees are reached after 3 poses (93 degrees), twice.
  const Trajectory trajectory = Turning({0, 31, 62, 93, 124, 155, 186, 217});
  EXPECT_EQ(AsPairs(SelectPairs(trajectory, Selection(90, DeltaUnit::kDegrees, false))), (Pairs{{0, 3}, {3, 6}}));
}

TEST(PairSelectionTest, DegreesAllPairsUseTheDirectAngleWithinTolerance) {
  // delta 90 +- 9 degrees: (0, 2) and (2, 4) turn 90 degrees; (0, 3) turns 100 and (3, 4) 80.
  const Trajectory trajectory = Turning({0, 45, 90, 100, 180});
  EXPECT_EQ(AsPairs(SelectPairs(trajectory, Selection(90, DeltaUnit::kDegrees, true))), (Pairs{{0, 2}, {2, 4}}));
}

TEST(PairSelectionTest, SecondsFollowThePathRuleOnElapsedTime) {
  // Poses every 0.25 s: 0.5 s is first reached at pose 2.
  const Trajectory trajectory = AlongX({0, 5, 1, 7, 2, 9, 3}, 0.25);
  EXPECT_EQ(AsPairs(SelectPairs(trajectory, Selection(0.5, DeltaUnit::kSeconds, false))), (Pairs{{2, 4}, {4, 6}}));
  EXPECT_EQ(AsPairs(SelectPairs(trajectory, Selection(0.5, DeltaUnit::kSeconds, true))),
            (Pairs{{0, 2}, {1, 3}, {2, 4}, {3, 5}, {4, 6}}));
}

TEST(PairSelectionTest, BadDeltasAndEmptySelectionsAreInputErrors) {
  const Trajectory trajectory = AlongX({0, 1, 2});
  EXPECT_THROW(SelectPairs(trajectory, Selection(1.5, DeltaUnit::kFrames, false)), InputError);
  EXPECT_THROW(SelectPairs(trajectory, Selection(0, DeltaUnit::kFrames, false)), InputError);
  EXPECT_THROW(SelectPairs(trajectory, Selection(-1, DeltaUnit::kMeters, false)), InputError);
  EXPECT_THROW(SelectPairs(trajectory, Selection(181, DeltaUnit::kDegrees, false)), InputError);
  EXPECT_THROW(SelectPairs(trajectory, Selection(std::nan(""), DeltaUnit::kSeconds, false)), InputError);
  EXPECT_THROW(SelectPairs(trajectory, Selection(1e300, DeltaUnit::kFrames, true)), InputError);
  try {
    SelectPairs(trajectory, Selection(10, DeltaUnit::kFrames, false));
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("delta = 10 (f"));
    EXPECT_THAT(error.what(), HasSubstr("--delta"));
  }
}

TEST(PairSelectionTest, DeltaUnitNamesRoundTripAndBadOnesListTheChoices) {
  for (DeltaUnit unit : {DeltaUnit::kFrames, DeltaUnit::kMeters, DeltaUnit::kSeconds, DeltaUnit::kDegrees}) {
    EXPECT_EQ(ParseDeltaUnit(DeltaUnitName(unit)), unit);
  }
  try {
    ParseDeltaUnit("rad");
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("f (frames), m (metres), s (seconds), d (degrees)"));
  }
}

RpeOptions Options(PoseRelation relation, double delta, DeltaUnit unit) {
  RpeOptions options;
  options.pose_relation = relation;
  options.delta = delta;
  options.delta_unit = unit;
  return options;
}

TEST(RpeTest, IdenticalTrajectoriesGiveZeroError) {
  Trajectory trajectory;
  for (int i = 0; i < 100; ++i) trajectory.Add(0.1 * i, Pose::Planar(std::cos(0.1 * i), std::sin(0.2 * i), 0.05 * i));
  for (PoseRelation relation : {PoseRelation::kTranslation, PoseRelation::kRotationDeg}) {
    const MetricResult result = Rpe(Options(relation, 1, DeltaUnit::kFrames)).Compute(trajectory, trajectory);
    EXPECT_EQ(result.statistics.n, 99u);
    EXPECT_LT(result.statistics.max, 1e-9);
  }
}

TEST(RpeTest, AStretchedEstimateHasTheStretchAsTranslationError) {
  // Reference steps 1 m along x; the estimate steps 1.1 m: every 1-frame pair is 0.1 m off,
  // every 2-frame pair 0.2 m.
  Trajectory reference;
  Trajectory estimate;
  for (int i = 0; i < 20; ++i) {
    reference.Add(i, Pose::Planar(i, 0.0, 0.0));
    estimate.Add(i, Pose::Planar(1.1 * i, 0.0, 0.0));
  }
  const MetricResult one = Rpe(Options(PoseRelation::kTranslation, 1, DeltaUnit::kFrames)).Compute(reference, estimate);
  EXPECT_NEAR(one.statistics.min, 0.1, 1e-9);
  EXPECT_NEAR(one.statistics.max, 0.1, 1e-9);
  EXPECT_EQ(one.statistics.n, 19u);
  EXPECT_EQ(one.unit, "m");
  const MetricResult two = Rpe(Options(PoseRelation::kTranslation, 2, DeltaUnit::kFrames)).Compute(reference, estimate);
  EXPECT_NEAR(two.statistics.mean, 0.2, 1e-9);
  EXPECT_EQ(two.statistics.n, 9u);
}

TEST(RpeTest, AHeadingDriftGivesItsRateAsRotationError) {
  // The estimate turns 1 degree more per pose than the reference.
  Trajectory reference;
  Trajectory estimate;
  for (int i = 0; i < 30; ++i) {
    reference.Add(i, Pose::Planar(i, 0.0, DegToRad(5.0 * i)));
    estimate.Add(i, Pose::Planar(i, 0.0, DegToRad(6.0 * i)));
  }
  const MetricResult result =
      Rpe(Options(PoseRelation::kRotationDeg, 1, DeltaUnit::kFrames)).Compute(reference, estimate);
  EXPECT_EQ(result.unit, "deg");
  EXPECT_NEAR(result.statistics.min, 1.0, 1e-9);
  EXPECT_NEAR(result.statistics.max, 1.0, 1e-9);
}

TEST(RpeTest, SpecificationNamesEveryOption) {
  RpeOptions options = Options(PoseRelation::kRotationDeg, 2.5, DeltaUnit::kMeters);
  options.all_pairs = true;
  options.alignment.mode = AlignmentMode::kSe2;
  const nlohmann::json specification = Rpe(options).Specification();
  EXPECT_EQ(specification.at("pose_relation"), "rot-deg");
  EXPECT_EQ(specification.at("delta"), 2.5);
  EXPECT_EQ(specification.at("delta_unit"), "m");
  EXPECT_EQ(specification.at("all_pairs"), true);
  EXPECT_EQ(specification.at("alignment"), "se2");
  EXPECT_EQ(specification.at("n_to_align"), -1);
  EXPECT_EQ(specification.at("t_max_diff_s"), 0.01);
  EXPECT_EQ(specification.at("t_offset_s"), 0.0);
}

TEST(RpeTest, BadOptionsFailAtConstruction) {
  EXPECT_THROW(Rpe(Options(PoseRelation::kTranslation, 0.5, DeltaUnit::kFrames)), InputError);
  EXPECT_THROW(Rpe(Options(PoseRelation::kTranslation, 200, DeltaUnit::kDegrees)), InputError);
  EXPECT_THROW(Rpe(Options(PoseRelation::kTranslation, -1, DeltaUnit::kSeconds)), InputError);
}

}  // namespace
}  // namespace slamsweep::evaluator
