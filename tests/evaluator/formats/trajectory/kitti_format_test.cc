#include "evaluator/formats/trajectory/kitti_format.h"

#include <gtest/gtest.h>

#include <numbers>

#include "tests/evaluator/formats/trajectory/trajectory_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using testing_util::ExpectInputError;

TEST(KittiFormatTest, ReadsRowMajorMatrixAndStampsByIndex) {
  // Pose 0: identity at (1, 2, 3). Pose 1: 90 deg about z (x -> y) at (5, 6, 0).
  const Trajectory t = ParseKittiPoses("1 0 0 1 0 1 0 2 0 0 1 3\n0 -1 0 5 1 0 0 6 0 0 1 0\n", "p.txt");
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t.stamps_s()[0], 0.0);
  EXPECT_EQ(t.stamps_s()[1], 1.0);
  EXPECT_TRUE(testing_util::SamePose(Pose{{1, 2, 3}, Eigen::Quaterniond::Identity()}, t.poses()[0], 1e-15));
  EXPECT_TRUE(testing_util::SamePose(Pose::Planar(5, 6, std::numbers::pi / 2), t.poses()[1], 1e-15));
}

TEST(KittiFormatTest, TimesFileGivesTheStamps) {
  testing::TempDir dir;
  testing::WriteFile(dir / "poses.txt", "1 0 0 1 0 1 0 2 0 0 1 3\n1 0 0 1 0 1 0 2 0 0 1 4\n");
  testing::WriteFile(dir / "times.txt", "0.000000e+00\n1.036200e-01\n");
  const Trajectory t = ReadKitti(dir / "poses.txt", dir / "times.txt");
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t.stamps_s()[1], 0.10362);
  EXPECT_EQ(t.poses()[1].position.z(), 4.0);
}

TEST(KittiFormatTest, CountMismatchNamesBothFilesAndCounts) {
  testing::TempDir dir;
  testing::WriteFile(dir / "poses.txt", "1 0 0 1 0 1 0 2 0 0 1 3\n1 0 0 1 0 1 0 2 0 0 1 4\n");
  testing::WriteFile(dir / "times.txt", "0\n0.1\n0.2\n");
  ExpectInputError([&] { ReadKitti(dir / "poses.txt", dir / "times.txt"); },
                   {"poses.txt", "times.txt", "2 poses", "3 stamps"});
}

TEST(KittiFormatTest, RoundTripKeepsStampsAndPoses) {
  for (bool planar : {true, false}) {
    const Trajectory original = testing_util::RandomTrajectory(200, planar, planar ? 3 : 4);
    testing::TempDir dir;
    WriteKitti(original, dir / "poses.kitti", dir / "times.txt");
    testing_util::ExpectSameTrajectory(original, ReadKitti(dir / "poses.kitti", dir / "times.txt"));
  }
}

TEST(KittiFormatTest, BadInputNamesFileAndLine) {
  ExpectInputError([] { ParseKittiPoses("1 0 0 1 0 1 0 2 0 0 1 3\n1 0 0 1 0 1 0 2 0 0\n", "p.txt"); },
                   {"p.txt:2", "12 fields"});
  ExpectInputError([] { ParseKittiPoses("1 0 0 1 0 1 0 2 0 0 1 3 7\n", "p.txt"); }, {"p.txt:1", "got 13"});
  ExpectInputError([] { ParseKittiPoses("1 0 0 x 0 1 0 2 0 0 1 3\n", "p.txt"); }, {"p.txt:1", "tx", "'x'"});
  ExpectInputError([] { ParseKittiPoses("1 0 0 1 0 nan 0 2 0 0 1 3\n", "p.txt"); }, {"p.txt:1", "r22"});
  ExpectInputError([] { ParseKittiPoses("2 0 0 1 0 1 0 2 0 0 1 3\n", "p.txt"); }, {"p.txt:1", "not a rotation"});
  ExpectInputError([] { ParseKittiPoses("-1 0 0 1 0 1 0 2 0 0 1 3\n", "p.txt"); }, {"p.txt:1", "det"});
  ExpectInputError([] { ParseKittiPoses("\n", "p.txt"); }, {"p.txt", "no poses"});
  ExpectInputError([] { ParseKittiTimes("0.1 0.2\n", "times.txt"); }, {"times.txt:1", "1 field"});
  ExpectInputError([] { ParseKittiTimes("", "times.txt"); }, {"times.txt", "no times"});
}

}  // namespace
}  // namespace slamsweep::evaluator
