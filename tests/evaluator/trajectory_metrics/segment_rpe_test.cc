#include "evaluator/trajectory_metrics/segment_rpe.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "evaluator/trajectory_metrics/rpe.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

SegmentRpeOptions Lengths(std::vector<double> lengths_m) {
  SegmentRpeOptions options;
  options.lengths_m = std::move(lengths_m);
  return options;
}

/// `count` poses along x, `step_m` apart, one per second; positions multiplied by `scale`.
Trajectory Straight(std::size_t count, double step_m, double scale = 1.0) {
  Trajectory trajectory;
  for (std::size_t i = 0; i < count; ++i) trajectory.Add(i, Pose::Planar(scale * step_m * i, 0.0, 0.0));
  return trajectory;
}

TEST(SegmentLengthsTest, TenToFiftyPercentOfThePathRoundedToMetres) {
  EXPECT_THAT(DefaultSegmentLengthsM(123.4), ElementsAre(12, 25, 37, 49, 62));
  EXPECT_THAT(DefaultSegmentLengthsM(400.0), ElementsAre(40, 80, 120, 160, 200));
  // A short path: 0.3 -> 0 (left out), 0.6, 0.9 and 1.2 -> 1 (once), 1.5 -> 2.
  EXPECT_THAT(DefaultSegmentLengthsM(3.0), ElementsAre(1, 2));
  EXPECT_TRUE(DefaultSegmentLengthsM(0.8).empty());
  EXPECT_TRUE(DefaultSegmentLengthsM(0.0).empty());
}

TEST(SegmentLengthsTest, PathLengthSumsTheSteps) {
  Trajectory square;
  square.Add(0, Pose::Planar(0, 0, 0));
  square.Add(1, Pose::Planar(3, 0, 0));
  square.Add(2, Pose::Planar(3, 4, 0));
  square.Add(3, Pose::Planar(0, 0, 0));
  EXPECT_DOUBLE_EQ(PathLengthM(square), 3.0 + 4.0 + 5.0);
  EXPECT_DOUBLE_EQ(PathLengthM(Trajectory()), 0.0);
}

TEST(SegmentRpeTest, RejectsBadLengths) {
  EXPECT_THAT([] { SegmentRpe(Lengths({})); }, ::testing::ThrowsMessage<InputError>(HasSubstr("at least one")));
  EXPECT_THAT([] { SegmentRpe(Lengths({5, -1})); }, ::testing::ThrowsMessage<InputError>(HasSubstr("> 0 m")));
  EXPECT_THAT([] { SegmentRpe(Lengths({5, 10, 5})); }, ::testing::ThrowsMessage<InputError>(HasSubstr("twice")));
  EXPECT_THAT([] { SegmentRpe(Lengths({std::nan("")})); }, ::testing::ThrowsMessage<InputError>(HasSubstr("finite")));
}

// evo's all-pairs rule keeps, near the end of the path, segments up to 10 % shorter than the length
// (the nearest end pose is the last one): the checks below therefore use each segment's own reference
// path, and check the exact drift on the segments of full length.
double ReferencePathBetween(const Trajectory& reference, const IndexPair& pair) {
  double length = 0.0;
  for (std::size_t k = pair.first + 1; k <= pair.second; ++k) {
    length += (reference.poses()[k].position - reference.poses()[k - 1].position).norm();
  }
  return length;
}

// A straight path whose estimate is 2 % too long: every segment is 2 % too long, so a segment of
// full length drifts by exactly 2 % of it, and none turns.
TEST(SegmentRpeTest, ScaleErrorOnAStraightPathIsItsPercentage) {
  const Trajectory reference = Straight(201, 0.1);  // 20 m
  const Trajectory estimate = Straight(201, 0.1, 1.02);
  const SegmentRpeResult result = SegmentRpe(Lengths({10, 2, 5})).Compute(reference, estimate);
  ASSERT_EQ(result.lengths.size(), 3u);
  EXPECT_EQ(result.lengths[0].length_m, 2.0);  // ascending
  EXPECT_EQ(result.lengths[2].length_m, 10.0);
  for (const SegmentLengthResult& segments : result.lengths) {
    SCOPED_TRACE(segments.length_m);
    const std::size_t steps = static_cast<std::size_t>(std::lround(segments.length_m / 0.1));
    std::size_t full = 0;
    for (std::size_t k = 0; k < segments.pairs.size(); ++k) {
      const double path = ReferencePathBetween(reference, segments.pairs[k]);
      EXPECT_GE(path, 0.9 * segments.length_m - 1e-9);
      EXPECT_LE(path, 1.1 * segments.length_m + 1e-9);
      EXPECT_NEAR(segments.translation_m[k], 0.02 * path, 1e-9);
      EXPECT_NEAR(segments.rotation_deg_per_m[k], 0.0, 1e-12);
      if (segments.pairs[k].second - segments.pairs[k].first == steps) {
        ++full;
        EXPECT_NEAR(segments.translation_pct[k], 2.0, 1e-9);
      }
    }
    EXPECT_EQ(full, 201u - steps);  // every start pose with a pose length_m further on
  }
}

// A circle of radius 10 m travelled at 0.5 m per pose, the estimate's positions 3 % further from the
// centre: a segment of arc length s has chord 2R sin(s / 2R), and its error is 3 % of the chord.
TEST(SegmentRpeTest, ScaleErrorOnACircleIsAPercentageOfTheChord) {
  constexpr double kRadius = 10.0;
  constexpr double kStepRad = 0.05;
  Trajectory reference;
  Trajectory estimate;
  for (int i = 0; i < 300; ++i) {
    const double angle = kStepRad * i;
    const double heading = angle + std::numbers::pi / 2;
    reference.Add(i, Pose::Planar(kRadius * std::cos(angle), kRadius * std::sin(angle), heading));
    estimate.Add(i, Pose::Planar(1.03 * kRadius * std::cos(angle), 1.03 * kRadius * std::sin(angle), heading));
  }
  const SegmentRpeResult result = SegmentRpe(Lengths({5, 20})).Compute(reference, estimate);
  for (const SegmentLengthResult& segments : result.lengths) {
    SCOPED_TRACE(segments.length_m);
    ASSERT_FALSE(segments.pairs.empty());
    std::vector<double> full;
    for (std::size_t k = 0; k < segments.pairs.size(); ++k) {
      const double arc = kRadius * kStepRad * static_cast<double>(segments.pairs[k].second - segments.pairs[k].first);
      const double chord = 2 * kRadius * std::sin(arc / (2 * kRadius));
      EXPECT_NEAR(segments.translation_pct[k], 100.0 * 0.03 * chord / segments.length_m, 1e-9);
      EXPECT_NEAR(segments.rotation_deg_per_m[k], 0.0, 1e-9);
      if (std::abs(arc - segments.length_m) < 1e-9) full.push_back(segments.translation_pct[k]);
    }
    ASSERT_FALSE(full.empty());
    const double d = segments.length_m;
    for (const double pct : full) EXPECT_NEAR(pct, 3.0 * std::sin(d / (2 * kRadius)) / (d / (2 * kRadius)), 1e-9);
  }
}

// A straight reference and an estimate that turns 0.01 rad per metre: a segment of s metres turns
// 0.01 s rad too much (0.573 deg/m on a full segment), and its position error is that of an arc of
// length s against its straight chord.
TEST(SegmentRpeTest, HeadingDriftIsDegreesPerMetre) {
  constexpr double kCurvature = 0.01;
  Trajectory reference;
  Trajectory estimate;
  for (int i = 0; i <= 400; ++i) {
    const double s = 0.1 * i;
    reference.Add(i, Pose::Planar(s, 0.0, 0.0));
    estimate.Add(i, Pose::Planar(std::sin(kCurvature * s) / kCurvature, (1 - std::cos(kCurvature * s)) / kCurvature,
                                 kCurvature * s));
  }
  const SegmentRpeResult result = SegmentRpe(Lengths({5, 10, 20})).Compute(reference, estimate);
  for (const SegmentLengthResult& segments : result.lengths) {
    SCOPED_TRACE(segments.length_m);
    const double d = segments.length_m;
    ASSERT_FALSE(segments.pairs.empty());
    std::size_t full = 0;
    for (std::size_t k = 0; k < segments.pairs.size(); ++k) {
      const double s = ReferencePathBetween(reference, segments.pairs[k]);
      const double expected_m =
          std::hypot(std::sin(kCurvature * s) / kCurvature - s, (1 - std::cos(kCurvature * s)) / kCurvature);
      EXPECT_NEAR(segments.rotation_deg_per_m[k], kCurvature * s * 180.0 / std::numbers::pi / d, 1e-9);
      EXPECT_NEAR(segments.translation_m[k], expected_m, 1e-9);
      EXPECT_NEAR(segments.translation_pct[k], 100.0 * expected_m / d, 1e-7);
      if (std::abs(s - d) < 1e-9) {
        ++full;
        EXPECT_NEAR(segments.rotation_deg_per_m[k], 0.5729577951308232, 1e-9);
      }
    }
    EXPECT_GT(full, 0u);
  }
}

TEST(SegmentRpeTest, ALengthLongerThanThePathHasNoSegmentsButIsNoError) {
  const SegmentRpeResult result = SegmentRpe(Lengths({5, 50})).Compute(Straight(101, 0.1), Straight(101, 0.1));
  ASSERT_EQ(result.lengths.size(), 2u);
  EXPECT_FALSE(result.lengths[0].pairs.empty());
  EXPECT_TRUE(result.lengths[1].pairs.empty());
  EXPECT_FALSE(result.lengths[1].translation_pct_statistics);
  const nlohmann::json json = result.ToJson();
  EXPECT_EQ(json["lengths"][1]["n"], 0);
  EXPECT_TRUE(json["lengths"][1]["translation_pct"].is_null());
  EXPECT_EQ(json["specification"]["pairs_from"], "reference");
  EXPECT_EQ(json["specification"]["lengths_m"], nlohmann::json::array({5.0, 50.0}));
}

// The segments do not depend on the estimate: they are the reference's, so an estimate that stands
// still is scored on the same segments as a good one.
TEST(SegmentRpeTest, SegmentsAreChosenOnTheReference) {
  const Trajectory reference = Straight(101, 0.1);
  Trajectory standing;
  for (int i = 0; i < 101; ++i) standing.Add(i, Pose::Planar(0.0, 0.0, 0.0));
  const SegmentRpeResult good = SegmentRpe(Lengths({5})).Compute(reference, Straight(101, 0.1, 1.01));
  const SegmentRpeResult bad = SegmentRpe(Lengths({5})).Compute(reference, standing);
  ASSERT_EQ(good.lengths[0].pairs.size(), bad.lengths[0].pairs.size());
  for (std::size_t k = 0; k < good.lengths[0].pairs.size(); ++k) {
    EXPECT_EQ(good.lengths[0].pairs[k].first, bad.lengths[0].pairs[k].first);
    EXPECT_EQ(good.lengths[0].pairs[k].second, bad.lengths[0].pairs[k].second);
  }
  // No motion at all: each segment's error is its whole reference chord, 100 % on a full segment.
  for (std::size_t k = 0; k < bad.lengths[0].pairs.size(); ++k) {
    EXPECT_NEAR(bad.lengths[0].translation_pct[k],
                100.0 * ReferencePathBetween(reference, bad.lengths[0].pairs[k]) / 5.0, 1e-9);
  }
}

// What `evo_rpe --delta D --delta_unit m --all_pairs --pairs_from_reference` computes, as the evo
// reference values of Rpe establish (evo_reference_test): at every length the segment RPE has the same
// pairs, in the same order, and the same translation and rotation errors.
void ExpectSameAsRpePerDelta(const Trajectory& reference, const Trajectory& estimate, double t_max_diff_s) {
  const std::vector<double> lengths = DefaultSegmentLengthsM(PathLengthM(reference));
  ASSERT_EQ(lengths.size(), 5u);
  SegmentRpeOptions options = Lengths(lengths);
  options.association.t_max_diff_s = t_max_diff_s;
  const SegmentRpeResult result = SegmentRpe(options).Compute(reference, estimate);
  for (const SegmentLengthResult& segments : result.lengths) {
    SCOPED_TRACE(segments.length_m);
    RpeOptions rpe;
    rpe.delta = segments.length_m;
    rpe.delta_unit = DeltaUnit::kMeters;
    rpe.all_pairs = true;
    rpe.pairs_from_reference = true;
    rpe.association.t_max_diff_s = t_max_diff_s;
    const MetricResult translation = Rpe(rpe).Compute(reference, estimate);
    rpe.pose_relation = PoseRelation::kRotationDeg;
    const MetricResult rotation = Rpe(rpe).Compute(reference, estimate);
    EXPECT_EQ(rotation.specification["pairs_from"], "reference");
    ASSERT_EQ(segments.translation_m.size(), translation.errors.size());
    ASSERT_GT(segments.translation_m.size(), 10u);
    for (std::size_t k = 0; k < translation.errors.size(); ++k) {
      EXPECT_DOUBLE_EQ(segments.translation_m[k], translation.errors[k]);
      EXPECT_DOUBLE_EQ(segments.translation_pct[k], 100.0 * translation.errors[k] / segments.length_m);
      EXPECT_DOUBLE_EQ(segments.rotation_deg_per_m[k], rotation.errors[k] / segments.length_m);
    }
    EXPECT_DOUBLE_EQ(segments.translation_m_statistics->rmse, translation.statistics.rmse);
  }
}

TEST(SegmentRpeTest, EqualsRpePerDeltaOnTheSyntheticEvoReference) {
  SLAMSWEEP_REQUIRE_SHARED(reference_path, "reference/trajectories/synth_gt.tum");
  SLAMSWEEP_REQUIRE_SHARED(estimate_path, "reference/trajectories/synth_est_se2.tum");
  ExpectSameAsRpePerDelta(ReadTum(reference_path), ReadTum(estimate_path), 0.01);
}

TEST(SegmentRpeTest, EqualsRpePerDeltaOnIntelWithGmapping) {
  SLAMSWEEP_REQUIRE_SHARED(reference_path, "reference/trajectories/intel_corrected.tum");
  SLAMSWEEP_REQUIRE_SHARED(estimate_path, "reference/trajectories/intel_gmapping.tum");
  ExpectSameAsRpePerDelta(ReadTum(reference_path), ReadTum(estimate_path), 0.01);
}

// Choosing the pairs on the reference is not evo's default: with pairs from the estimate the pairs
// differ (the option reaches the selection).
TEST(SegmentRpeTest, PairsFromTheEstimateDiffer) {
  const Trajectory reference = Straight(201, 0.1);
  const Trajectory estimate = Straight(201, 0.1, 1.25);
  RpeOptions rpe;
  rpe.delta = 5;
  rpe.delta_unit = DeltaUnit::kMeters;
  rpe.all_pairs = true;
  const std::size_t from_estimate = Rpe(rpe).Compute(reference, estimate).errors.size();
  rpe.pairs_from_reference = true;
  const std::size_t from_reference = Rpe(rpe).Compute(reference, estimate).errors.size();
  EXPECT_EQ(from_reference, FindPairs(reference, {5, DeltaUnit::kMeters, true, 0.1}).size());
  EXPECT_EQ(from_estimate, FindPairs(estimate, {5, DeltaUnit::kMeters, true, 0.1}).size());
  EXPECT_GT(from_estimate, from_reference);  // 5 m of the estimate are 4 m of the reference: 40 poses, not 50
}

}  // namespace
}  // namespace slamsweep::evaluator
