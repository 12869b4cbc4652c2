#include "evaluator/formats/trajectory/csv_format.h"

#include <gtest/gtest.h>

#include <sstream>

#include "tests/evaluator/formats/trajectory/trajectory_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using testing_util::ExpectInputError;

TEST(CsvFormatTest, ReadsSe2ColumnsInAnyOrder) {
  const Trajectory t = ParseCsv("theta, y ,X,Timestamp\n0.5,2,1,10.25\n", "t.csv");
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t.stamps_s()[0], 10.25);
  EXPECT_TRUE(testing_util::SamePose(Pose::Planar(1, 2, 0.5), t.poses()[0], 1e-15));
}

TEST(CsvFormatTest, ReadsSe3Columns) {
  const Trajectory t = ParseCsv("# exported\ntimestamp,x,y,z,qx,qy,qz,qw\n1,1,2,3,0,0,0,2\n2,1,2,3,1,0,0,0\n", "t.csv");
  ASSERT_EQ(t.size(), 2u);
  // The quaternion is normalised: (0, 0, 0, 2) is the identity.
  EXPECT_TRUE(testing_util::SamePose(Pose{{1, 2, 3}, Eigen::Quaterniond::Identity()}, t.poses()[0], 1e-15));
  EXPECT_TRUE(testing_util::SamePose(Pose{{1, 2, 3}, Eigen::Quaterniond(0, 1, 0, 0)}, t.poses()[1], 1e-15));
}

TEST(CsvFormatTest, WriterPicksSe2ForPlanarAndSe3Otherwise) {
  std::ostringstream planar;
  WriteCsv(testing_util::RandomTrajectory(3, true, 1), planar);
  EXPECT_TRUE(planar.str().starts_with("timestamp,x,y,theta\n"));
  std::ostringstream general;
  WriteCsv(testing_util::RandomTrajectory(3, false, 1), general);
  EXPECT_TRUE(general.str().starts_with("timestamp,x,y,z,qx,qy,qz,qw\n"));
}

TEST(CsvFormatTest, RoundTripKeepsStampsAndPoses) {
  for (bool planar : {true, false}) {
    const Trajectory original = testing_util::RandomTrajectory(200, planar, planar ? 21 : 22);
    testing::TempDir dir;
    WriteCsv(original, dir / "t.csv");
    testing_util::ExpectSameTrajectory(original, ReadCsv(dir / "t.csv"));
  }
}

TEST(CsvFormatTest, BadHeadersSayWhatIsExpected) {
  ExpectInputError([] { ParseCsv("", "t.csv"); }, {"t.csv", "header", "timestamp,x,y,theta"});
  ExpectInputError([] { ParseCsv("timestamp,x,y\n1,2,3\n", "t.csv"); }, {"t.csv:1", "no column 'z'"});
  ExpectInputError([] { ParseCsv("timestamp,x,y,thetta\n1,2,3,4\n", "t.csv"); }, {"t.csv:1", "'thetta'"});
  ExpectInputError([] { ParseCsv("timestamp,x,y,theta,qx\n1,2,3,4,5\n", "t.csv"); }, {"t.csv:1", "'qx'", "SE(2)"});
  ExpectInputError([] { ParseCsv("timestamp,x,x,y,theta\n", "t.csv"); }, {"t.csv:1", "more than once"});
  ExpectInputError([] { ParseCsv("timestamp,x,y,theta\n", "t.csv"); }, {"t.csv", "no poses"});
}

TEST(CsvFormatTest, BadRowsNameFileLineAndColumn) {
  ExpectInputError([] { ParseCsv("timestamp,x,y,theta\n1,2,3,4\n2,3,4\n", "t.csv"); }, {"t.csv:3", "4 comma"});
  ExpectInputError([] { ParseCsv("timestamp,x,y,theta\n1,2,abc,4\n", "t.csv"); }, {"t.csv:2", "(y)", "'abc'"});
  ExpectInputError([] { ParseCsv("timestamp,x,y,theta\n1,2,3,nan\n", "t.csv"); }, {"t.csv:2", "theta"});
  ExpectInputError([] { ParseCsv("timestamp,x,y,theta\n1,,3,4\n", "t.csv"); }, {"t.csv:2", "(x)"});
  ExpectInputError([] { ParseCsv("timestamp,x,y,z,qx,qy,qz,qw\n1,2,3,4,0,0,0,0\n", "t.csv"); },
                   {"t.csv:2", "zero norm"});
}

}  // namespace
}  // namespace slamsweep::evaluator
