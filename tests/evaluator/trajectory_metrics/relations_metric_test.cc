#include "evaluator/trajectory_metrics/relations_metric.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

// A curving path at 1 Hz over [0, 20] s.
Trajectory Path() {
  Trajectory trajectory;
  for (int i = 0; i <= 20; ++i) trajectory.Add(i, Pose::Planar(std::cos(0.3 * i) * 5.0, 0.4 * i, 0.2 * i));
  return trajectory;
}

Relation Between(const Trajectory& trajectory, std::size_t i, std::size_t j) {
  return Relation{trajectory.stamps_s()[i], trajectory.stamps_s()[j],
                  Relative(trajectory.poses()[i], trajectory.poses()[j])};
}

TEST(RelationsMetricTest, AnEstimateEqualToTheReferenceHasZeroError) {
  const Trajectory reference = Path();
  const Relations relations = {Between(reference, 0, 1), Between(reference, 3, 9), Between(reference, 20, 2)};
  const RelationsResult result = RelationsMetric(RelationsOptions{}).Compute(reference, relations);
  EXPECT_EQ(result.used, 3u);
  EXPECT_EQ(result.not_covered, 0u);
  EXPECT_LT(result.translation_abs_mean_m, 1e-12);
  EXPECT_LT(result.rotation_abs_mean_deg, 1e-6);
}

TEST(RelationsMetricTest, AKnownPerturbationGivesTheKnownError) {
  // Estimate: at t = 1 s it has moved (1.3, 0.4) instead of the expected (1, 0): error 0.5 m, 0 deg.
  // From t = 2 to 3 s it turns 10 degrees in place where no motion is expected: 0 m, 10 deg.
  Trajectory estimate;
  estimate.Add(0.0, Pose::Planar(0.0, 0.0, 0.0));
  estimate.Add(1.0, Pose::Planar(1.3, 0.4, 0.0));
  estimate.Add(2.0, Pose::Planar(5.0, 5.0, 0.0));
  estimate.Add(3.0, Pose::Planar(5.0, 5.0, DegToRad(10.0)));
  const Relations relations = {Relation{0.0, 1.0, Pose::Planar(1.0, 0.0, 0.0)}, Relation{2.0, 3.0, Pose()}};
  const RelationsResult result = RelationsMetric(RelationsOptions{}).Compute(estimate, relations);
  EXPECT_EQ(result.used, 2u);
  // Errors 0.5 and 0 m; 0 and 10 deg. Population mean and std of each pair.
  EXPECT_NEAR(result.translation_abs_mean_m, 0.25, 1e-12);
  EXPECT_NEAR(result.translation_abs_std_m, 0.25, 1e-12);
  EXPECT_NEAR(result.translation_sq_mean_m2, 0.125, 1e-12);
  EXPECT_NEAR(result.translation_sq_std_m2, 0.125, 1e-12);
  EXPECT_NEAR(result.rotation_abs_mean_deg, 5.0, 1e-9);
  EXPECT_NEAR(result.rotation_abs_std_deg, 5.0, 1e-9);
  EXPECT_NEAR(result.rotation_sq_mean_deg2, 50.0, 1e-7);
  EXPECT_NEAR(result.rotation_sq_std_deg2, 50.0, 1e-7);
}

TEST(RelationsMetricTest, ErrorIsTakenInTheFrameOfTheExpectedRelation) {
  // E = (P1^-1 P2) * expected^-1 with P1^-1 P2 = (yaw 90 deg, (1, 0)) and expected = (yaw 90 deg, (0, 0)):
  // E = (identity rotation, (1, 0)): 1 m and 0 degrees.
  Trajectory estimate;
  estimate.Add(0.0, Pose::Planar(0.0, 0.0, 0.0));
  estimate.Add(1.0, Pose::Planar(1.0, 0.0, DegToRad(90.0)));
  const Relations relations = {Relation{0.0, 1.0, Pose::Planar(0.0, 0.0, DegToRad(90.0))}};
  const RelationsResult result = RelationsMetric(RelationsOptions{}).Compute(estimate, relations);
  EXPECT_NEAR(result.translation_abs_mean_m, 1.0, 1e-12);
  EXPECT_NEAR(result.rotation_abs_mean_deg, 0.0, 1e-6);
}

TEST(RelationsMetricTest, InterpolatesBetweenRecordedPoses) {
  Trajectory estimate;
  estimate.Add(0.0, Pose::Planar(0.0, 0.0, 0.0));
  estimate.Add(2.0, Pose::Planar(2.0, 0.0, 0.0));
  const Relations relations = {Relation{0.5, 1.5, Pose::Planar(1.0, 0.0, 0.0)}};
  const RelationsResult result = RelationsMetric(RelationsOptions{}).Compute(estimate, relations);
  EXPECT_EQ(result.used, 1u);
  EXPECT_LT(result.translation_abs_mean_m, 1e-12);
}

TEST(RelationsMetricTest, RelationsOutsideTheSpanAreSkippedAndCounted) {
  const Trajectory reference = Path();
  const Relations relations = {Between(reference, 0, 5), Relation{-1.0, 2.0, Pose()}, Relation{19.0, 20.5, Pose()},
                               Relation{30.0, 31.0, Pose()}};
  const RelationsResult result = RelationsMetric(RelationsOptions{}).Compute(reference, relations);
  EXPECT_EQ(result.used, 1u);
  EXPECT_EQ(result.not_covered, 3u);
  const nlohmann::json json = result.ToJson();
  EXPECT_EQ(json.at("used"), 1);
  EXPECT_EQ(json.at("not_covered"), 3);
  EXPECT_EQ(json.at("specification").at("t_offset_s"), 0.0);
  EXPECT_TRUE(json.contains("rotation_sq_std_deg2"));
}

TEST(RelationsMetricTest, OffsetMovesRelationStampsOntoTheEstimateClock) {
  const Trajectory reference = Path();
  Relation relation = Between(reference, 2, 4);
  relation.t1_s -= 100.0;
  relation.t2_s -= 100.0;
  EXPECT_THROW(RelationsMetric(RelationsOptions{}).Compute(reference, {relation}), InputError);
  const RelationsResult result = RelationsMetric(RelationsOptions{100.0}).Compute(reference, {relation});
  EXPECT_EQ(result.used, 1u);
  EXPECT_LT(result.translation_abs_mean_m, 1e-12);
}

TEST(RelationsMetricTest, NoUsableRelationNamesBothTimeRanges) {
  const Trajectory estimate = Path();
  const Relations relations = {Relation{100.0, 101.0, Pose()}, Relation{102.0, 103.5, Pose()}};
  try {
    RelationsMetric(RelationsOptions{}).Compute(estimate, relations);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr(DescribeTimeRange(estimate)));
    EXPECT_THAT(error.what(), HasSubstr("[100.000000, 103.500000] s (2 relations"));
  }
  EXPECT_THROW(RelationsMetric(RelationsOptions{}).Compute(estimate, Relations{}), InputError);
  EXPECT_THROW(RelationsMetric(RelationsOptions{}).Compute(Trajectory(), relations), InputError);
  EXPECT_THROW(RelationsMetric(RelationsOptions{std::nan("")}), InputError);
}

}  // namespace
}  // namespace slamsweep::evaluator
