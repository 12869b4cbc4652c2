#include "evaluator/formats/trajectory/tum_format.h"

#include <gtest/gtest.h>

#include <sstream>

#include "tests/evaluator/formats/trajectory/trajectory_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using testing_util::ExpectInputError;

TEST(TumFormatTest, RoundTripKeepsStampsAndPoses) {
  for (bool planar : {true, false}) {
    const Trajectory original = testing_util::RandomTrajectory(200, planar, planar ? 1 : 2);
    testing::TempDir dir;
    WriteTum(original, dir / "t.tum");
    testing_util::ExpectSameTrajectory(original, ReadTum(dir / "t.tum"));
  }
}

TEST(TumFormatTest, ReadsAHandWrittenLine) {
  const Trajectory t = ParseTum("# comment\n1.5 1 2 3 0 0 0.7071067811865476 0.7071067811865476\n", "mem.tum");
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t.stamps_s()[0], 1.5);
  EXPECT_TRUE(testing_util::SamePose(Pose{{1, 2, 3}, Eigen::Quaterniond(0.7071067811865476, 0, 0, 0.7071067811865476)},
                                     t.poses()[0], 1e-12));
}

TEST(TumFormatTest, BadInputNamesFileAndLine) {
  ExpectInputError([] { ParseTum("0 1 2 3 0 0 0 1\n1 1 2 3 0 0\n", "t.tum"); }, {"t.tum:2", "expected 8 fields"});
  ExpectInputError([] { ParseTum("0 1 2 abc 0 0 0 1\n", "t.tum"); }, {"t.tum:1", "tz", "abc"});
  ExpectInputError([] { ParseTum("0 1 nan 3 0 0 0 1\n", "t.tum"); }, {"t.tum:1", "ty"});
  ExpectInputError([] { ParseTum("", "t.tum"); }, {"t.tum", "no poses"});
}

}  // namespace
}  // namespace slamsweep::evaluator
