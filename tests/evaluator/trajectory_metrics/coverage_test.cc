// Coverage by time span, checked on hand-made stamps.
#include "evaluator/trajectory_metrics/coverage.h"

#include <gtest/gtest.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

Trajectory Stamps(double start_s, double end_s, int count) {
  Trajectory trajectory;
  for (int i = 0; i < count; ++i) {
    const double t = count == 1 ? start_s : start_s + (end_s - start_s) * i / (count - 1);
    trajectory.Add(t, Pose::Planar(t, 0.0, 0.0));
  }
  return trajectory;
}

TEST(CoverageTest, ADenserRunAgainstSparseKeyframesIsFullyCovered) {
  // 2,725 scan poses against 910 keyframes over the same 100 s: the count of poses does not matter.
  EXPECT_DOUBLE_EQ(ComputeCoverage(Stamps(0, 100, 910), Stamps(0, 100, 2725)).fraction, 1.0);
  // And the other way round: a sparse estimate spanning the whole run covers it.
  EXPECT_DOUBLE_EQ(ComputeCoverage(Stamps(0, 100, 2725), Stamps(0, 100, 20)).fraction, 1.0);
}

TEST(CoverageTest, ARunThatStopsEarlyOrStartsLateCoversItsSpanOnly) {
  const Trajectory reference = Stamps(10, 110, 101);
  const TrajectoryCoverage early = ComputeCoverage(reference, Stamps(10, 60, 500));
  EXPECT_DOUBLE_EQ(early.fraction, 0.5);
  EXPECT_DOUBLE_EQ(early.estimate_end_s, 60.0);
  EXPECT_DOUBLE_EQ(early.reference_start_s, 10.0);
  EXPECT_DOUBLE_EQ(ComputeCoverage(reference, Stamps(85, 200, 50)).fraction, 0.25);  // 85..110 of 10..110
  EXPECT_DOUBLE_EQ(ComputeCoverage(reference, Stamps(200, 300, 5)).fraction, 0.0);   // on another clock
  EXPECT_DOUBLE_EQ(ComputeCoverage(reference, Trajectory()).fraction, 0.0);
}

TEST(CoverageTest, AOneStampReferenceAndAnEmptyOne) {
  EXPECT_DOUBLE_EQ(ComputeCoverage(Stamps(5, 5, 1), Stamps(0, 10, 3)).fraction, 1.0);
  EXPECT_DOUBLE_EQ(ComputeCoverage(Stamps(50, 50, 1), Stamps(0, 10, 3)).fraction, 0.0);
  EXPECT_THROW(ComputeCoverage(Trajectory(), Stamps(0, 10, 3)), InputError);
}

}  // namespace
}  // namespace slamsweep::evaluator
