#include "evaluator/formats/trajectory/mrpt_path_format.h"

#include <gtest/gtest.h>

#include <sstream>

#include "tests/evaluator/formats/trajectory/trajectory_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using testing_util::ExpectInputError;

// Lines as icp-slam prints them ("%i %f %f %f": step x y phi).
constexpr const char* kIcpPath =
    "0 0.000000 0.000000 0.000000\n1 0.512300 -0.020000 0.100000\n2 1.000000 0.250000 -3.000000\n";

TEST(MrptPathFormatTest, ReadsIcpSlamLayoutWithSteps) {
  const MrptPath path = ParseMrptPath(kIcpPath, "log_estimated_path.txt");
  EXPECT_EQ(path.layout, MrptPathLayout::kIcpSlam);
  ASSERT_EQ(path.poses.size(), 3u);
  EXPECT_EQ(path.steps, (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_TRUE(path.stamps_s.empty());
  EXPECT_TRUE(testing_util::SamePose(Pose::Planar(0.5123, -0.02, 0.1), path.poses[1], 1e-15));
  EXPECT_TRUE(testing_util::SamePose(Pose::Planar(1.0, 0.25, -3.0), path.poses[2], 1e-15));
  // Without stamps the step index stands in for time.
  const Trajectory t = MrptPathTrajectory(path);
  EXPECT_EQ(t.stamps_s(), (std::vector<double>{0.0, 1.0, 2.0}));
}

TEST(MrptPathFormatTest, ReadsRbpfSlamLayoutWithTimestamps) {
  // "%u %f %f %f %f %f %f %f": step x y z yaw pitch roll timestamp.
  const MrptPath path =
      ParseMrptPath("0 1.000000 2.000000 0.000000 1.570796 0.000000 0.000000 1500000000.250000\n", "p.txt");
  EXPECT_EQ(path.layout, MrptPathLayout::kRbpfSlam);
  ASSERT_EQ(path.stamps_s.size(), 1u);
  EXPECT_EQ(path.stamps_s[0], 1500000000.25);
  EXPECT_TRUE(testing_util::SamePose(Pose::Planar(1.0, 2.0, 1.570796), path.poses[0], 1e-15));
  EXPECT_EQ(MrptPathTrajectory(path).stamps_s()[0], 1500000000.25);
}

TEST(MrptPathFormatTest, StepStampsMapStepsToTimes) {
  testing::TempDir dir;
  testing::WriteFile(dir / "log_estimated_path.txt", "3 0 0 0\n5 1 0 0\n");
  const std::vector<double> stamps = {10.0, 10.5, 11.0, 11.5, 12.0, 12.5};
  const Trajectory t = ReadMrptPath(dir / "log_estimated_path.txt", stamps);
  EXPECT_EQ(t.stamps_s(), (std::vector<double>{11.5, 12.5}));
  const std::vector<double> too_few = {10.0, 10.5, 11.0, 11.5};
  ExpectInputError([&] { ReadMrptPath(dir / "log_estimated_path.txt", too_few); },
                   {"log_estimated_path.txt:2", "step 5", "4 step stamps"});
}

TEST(MrptPathFormatTest, RoundTripKeepsStampsAndPoses) {
  for (bool planar : {true, false}) {
    const Trajectory original = testing_util::RandomTrajectory(200, planar, planar ? 5 : 6);
    testing::TempDir dir;
    WriteMrptPath(original, dir / "log_estimated_path.txt", MrptPathLayout::kRbpfSlam);
    testing_util::ExpectSameTrajectory(original, MrptPathTrajectory(ReadMrptPath(dir / "log_estimated_path.txt")));
  }
}

TEST(MrptPathFormatTest, IcpLayoutRoundTripNeedsTheStepStamps) {
  const Trajectory original = testing_util::RandomTrajectory(100, true, 8);
  testing::TempDir dir;
  WriteMrptPath(original, dir / "log_estimated_path.txt", MrptPathLayout::kIcpSlam);
  testing_util::ExpectSameTrajectory(original, ReadMrptPath(dir / "log_estimated_path.txt", original.stamps_s()));
}

TEST(MrptPathFormatTest, IcpLayoutRejects3dPoses) {
  std::ostringstream out;
  ExpectInputError([&] { WriteMrptPath(testing_util::RandomTrajectory(3, false, 9), out, MrptPathLayout::kIcpSlam); },
                   {"pose 0", "not planar"});
}

TEST(MrptPathFormatTest, BadInputNamesFileAndLine) {
  ExpectInputError([] { ParseMrptPath("0 1 2 3\n1 1 2\n", "p.txt"); }, {"p.txt:2", "4 fields"});
  ExpectInputError([] { ParseMrptPath("0 1 2 3\n1 1 2 3 4 5 6 7\n", "p.txt"); }, {"p.txt:2", "like the first line"});
  ExpectInputError([] { ParseMrptPath("0 1 2 3 4\n", "p.txt"); }, {"p.txt:1", "4 fields", "8 fields"});
  ExpectInputError([] { ParseMrptPath("0 1 y 3\n", "p.txt"); }, {"p.txt:1", "(y)", "'y'"});
  ExpectInputError([] { ParseMrptPath("0 1 2 nan\n", "p.txt"); }, {"p.txt:1", "phi"});
  ExpectInputError([] { ParseMrptPath("0.5 1 2 3\n", "p.txt"); }, {"p.txt:1", "step", "integer"});
  ExpectInputError([] { ParseMrptPath("-1 1 2 3\n", "p.txt"); }, {"p.txt:1", "step", ">= 0"});
  ExpectInputError([] { ParseMrptPath("% only a comment\n", "p.txt"); }, {"p.txt", "no poses"});
}

}  // namespace
}  // namespace slamsweep::evaluator
