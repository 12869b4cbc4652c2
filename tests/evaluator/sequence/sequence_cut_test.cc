#include "evaluator/sequence/sequence_cut.h"

#include <gtest/gtest.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

/// Scans at 0, 1, ..., 9 s with odometry; a reference at the same stamps; relations 0-2, 3-5, 7-9.
Sequence TenScans() {
  Sequence sequence;
  sequence.name = "ten";
  Trajectory reference;
  for (int i = 0; i < 10; ++i) {
    LaserScan scan;
    scan.stamp_s = i;
    scan.ranges_m = {1.0f};
    scan.angle_increment_rad = 0.1;
    scan.range_max_m = 10.0;
    sequence.scans.push_back(scan);
    sequence.odometry.Add(i, Pose::Planar(i, 0, 0));
    reference.Add(i, Pose::Planar(i, 0, 0));
  }
  sequence.reference = reference;
  sequence.relations = Relations{{0, 2, Pose()}, {3, 5, Pose()}, {7, 9, Pose()}};
  return sequence;
}

TEST(SequenceCutTest, AScanRangeKeepsItsOdometryReferenceAndTheRelationsInsideIt) {
  const Sequence cut = KeepScanRange(TenScans(), 3, 4);  // scans at 3..6 s
  ASSERT_EQ(cut.scans.size(), 4u);
  EXPECT_EQ(cut.scans.front().stamp_s, 3.0);
  EXPECT_EQ(cut.odometry.size(), 4u);
  EXPECT_EQ(cut.odometry.stamps_s().front(), 3.0);
  ASSERT_TRUE(cut.reference.has_value());
  EXPECT_EQ(cut.reference->size(), 4u);
  ASSERT_TRUE(cut.relations.has_value());
  ASSERT_EQ(cut.relations->size(), 1u);
  EXPECT_EQ(cut.relations->front().t1_s, 3.0);
  EXPECT_EQ(cut.relations_outside_log, 2u);
  EXPECT_NO_THROW(ValidateSequence(cut));
}

TEST(SequenceCutTest, ACutOfTheFirstScansIsMaxScans) {
  const Sequence cut = KeepScanRange(TenScans(), 0, 6);
  EXPECT_EQ(cut.scans.size(), 6u);
  EXPECT_EQ(cut.relations->size(), 2u);
  EXPECT_EQ(cut.relations_outside_log, 1u);
  // More scans than the sequence has: unchanged.
  const Sequence whole = KeepScanRange(TenScans(), 0, 50);
  EXPECT_EQ(whole.scans.size(), 10u);
  EXPECT_EQ(whole.relations_outside_log, 0u);
}

// A span between scans keeps the scans just outside it, so every stamp of the span lies between two scans.
TEST(SequenceCutTest, ATimeSpanKeepsTheScansThatCoverIt) {
  const Sequence cut = KeepTimeSpan(TenScans(), 2.5, 5.5);
  ASSERT_EQ(cut.scans.size(), 5u);  // 2, 3, 4, 5, 6
  EXPECT_EQ(cut.scans.front().stamp_s, 2.0);
  EXPECT_EQ(cut.scans.back().stamp_s, 6.0);
  EXPECT_EQ(cut.relations->size(), 1u);  // 3-5
  const Sequence exact = KeepTimeSpan(TenScans(), 3.0, 5.0);
  EXPECT_EQ(exact.scans.size(), 3u);
  EXPECT_THROW(KeepTimeSpan(TenScans(), 20.0, 30.0), InputError);
  EXPECT_THROW(KeepScanRange(TenScans(), 10, 5), InputError);
}

}  // namespace
}  // namespace slamsweep::evaluator
