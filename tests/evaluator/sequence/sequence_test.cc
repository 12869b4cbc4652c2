#include "evaluator/sequence/sequence.h"

#include <gtest/gtest.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

Sequence TwoScans() {
  Sequence sequence;
  sequence.name = "two";
  for (double stamp_s : {1.0, 2.0}) {
    LaserScan scan;
    scan.stamp_s = stamp_s;
    scan.ranges_m = {1.0f, 2.0f};
    scan.angle_min_rad = -0.5;
    scan.angle_increment_rad = 1.0;
    scan.range_max_m = 10.0;
    sequence.scans.push_back(scan);
    sequence.odometry.Add(stamp_s, Pose::Planar(stamp_s, 0.0, 0.0));
  }
  return sequence;
}

std::string ErrorOf(const Sequence& sequence) {
  try {
    ValidateSequence(sequence);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(valid)";
}

TEST(SequenceTest, AWellFormedSequenceIsValid) { EXPECT_EQ(ErrorOf(TwoScans()), "(valid)"); }

TEST(SequenceTest, EachBrokenInvariantIsNamed) {
  Sequence sequence = TwoScans();
  sequence.scans[1].stamp_s = 1.0;
  EXPECT_EQ(ErrorOf(sequence), "sequence 'two': scan 1: stamp 1 s does not come after the previous scan's 1 s");

  sequence = TwoScans();
  sequence.odometry = Trajectory({1.0}, {Pose()});
  EXPECT_EQ(ErrorOf(sequence), "sequence 'two': expected one odometry pose per scan (2), got 1");

  sequence = TwoScans();
  sequence.odometry = Trajectory({1.0, 2.5}, {Pose(), Pose()});
  EXPECT_EQ(ErrorOf(sequence), "sequence 'two': odometry pose 1 has stamp 2.5 s, its scan 2 s");

  sequence = TwoScans();
  sequence.scans[0].ranges_m.clear();
  EXPECT_EQ(ErrorOf(sequence), "sequence 'two': scan 0: has no beams");

  sequence = TwoScans();
  sequence.scans[0].angle_increment_rad = 0.0;
  EXPECT_NE(ErrorOf(sequence).find("scan 0: expected a finite start angle and a finite non-zero angle increment"),
            std::string::npos);

  sequence = TwoScans();
  sequence.scans[1].range_max_m = 0.0;
  EXPECT_NE(ErrorOf(sequence).find("scan 1: expected 0 <= range_min_m < range_max_m"), std::string::npos);
}

}  // namespace
}  // namespace slamsweep::evaluator
