#include "evaluator/formats/trajectory/trajectory_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/evaluator/formats/trajectory/trajectory_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;
using testing_util::ExpectInputError;

TEST(TrajectoryFormatTest, NamesRoundTrip) {
  for (TrajectoryFormat format : {TrajectoryFormat::kAuto, TrajectoryFormat::kTum, TrajectoryFormat::kKitti,
                                  TrajectoryFormat::kMrptPath, TrajectoryFormat::kCarmen, TrajectoryFormat::kCsv}) {
    EXPECT_EQ(ParseTrajectoryFormat(TrajectoryFormatName(format)), format);
  }
  EXPECT_EQ(ParseTrajectoryFormat("KITTI"), TrajectoryFormat::kKitti);
  EXPECT_FALSE(ParseTrajectoryFormat("g2o").has_value());
}

TEST(TrajectoryFormatTest, DetectsByName) {
  EXPECT_EQ(DetectTrajectoryFormat("a/log_estimated_path.txt", ""), TrajectoryFormat::kMrptPath);
  EXPECT_EQ(DetectTrajectoryFormat("a.csv", ""), TrajectoryFormat::kCsv);
  EXPECT_EQ(DetectTrajectoryFormat("a.log", ""), TrajectoryFormat::kCarmen);
  EXPECT_EQ(DetectTrajectoryFormat("a.log.gz", ""), TrajectoryFormat::kCarmen);
  EXPECT_EQ(DetectTrajectoryFormat("a.CLF", ""), TrajectoryFormat::kCarmen);
  // GMapping's .gfs is its own format, not CARMEN: the name alone says nothing.
  EXPECT_THROW(DetectTrajectoryFormat("a.gfs", ""), InputError);
  EXPECT_EQ(DetectTrajectoryFormat("a.kitti", ""), TrajectoryFormat::kKitti);
  EXPECT_EQ(DetectTrajectoryFormat("a.tum", ""), TrajectoryFormat::kTum);
}

TEST(TrajectoryFormatTest, DetectsByContent) {
  EXPECT_EQ(DetectTrajectoryFormat("a.txt", "# tum\n1.0 1 2 3 0 0 0 1\n"), TrajectoryFormat::kTum);
  EXPECT_EQ(DetectTrajectoryFormat("a.txt", "1 0 0 1 0 1 0 2 0 0 1 3\n"), TrajectoryFormat::kKitti);
  EXPECT_EQ(DetectTrajectoryFormat("a.txt", "% icp\n0 0.5 0.25 0.1\n"), TrajectoryFormat::kMrptPath);
  EXPECT_EQ(DetectTrajectoryFormat("a.txt", "0 1.0 2.0 0.0 0.3 0.0 0.0 1500000000.25\n"), TrajectoryFormat::kMrptPath);
  EXPECT_EQ(DetectTrajectoryFormat("a", "PARAM a b\nFLASER 0 1 2 3 1 2 3 4 h 4\n"), TrajectoryFormat::kCarmen);
  EXPECT_EQ(DetectTrajectoryFormat("a.dat", "timestamp, x, y, theta\n"), TrajectoryFormat::kCsv);
}

TEST(TrajectoryFormatTest, FailedDetectionListsEveryFormatTried) {
  ExpectInputError(
      [] { DetectTrajectoryFormat("run.txt", "\n1 2 3 4 5\n"); },
      {"run.txt:2", "5 fields", "TUM", "KITTI", "MRPT", "CARMEN", "CSV", "12 fields", "timestamp,x,y,theta"});
  ExpectInputError([] { DetectTrajectoryFormat("run.txt", "# only comments\n"); }, {"run.txt", "no data lines", "TUM"});
  // A relations line has 8 fields but is neither TUM nor an MRPT path.
  ExpectInputError([] { DetectTrajectoryFormat("r.txt", "976052905.1673 976052911.8854 -0.05 -0.12 0 0 0 -1.68\n"); },
                   {"r.txt:1", "not a unit quaternion", "relations"});
}

TEST(TrajectoryFileTest, EveryFormatRoundTripsThroughTheFrontDoor) {
  struct Case {
    const char* name;
    TrajectoryFormat format;
    bool planar_only;
  };
  const Case cases[] = {{"t.tum", TrajectoryFormat::kTum, false},
                        {"t.kitti", TrajectoryFormat::kKitti, false},
                        {"log_estimated_path.txt", TrajectoryFormat::kMrptPath, false},
                        {"t.log", TrajectoryFormat::kCarmen, true},
                        {"t.csv", TrajectoryFormat::kCsv, false}};
  for (const Case& c : cases) {
    for (bool planar : {true, false}) {
      if (c.planar_only && !planar) continue;
      SCOPED_TRACE(std::string(c.name) + (planar ? " planar" : " 3D"));
      const Trajectory original = testing_util::RandomTrajectory(50, planar, 40);
      testing::TempDir dir;
      TrajectoryWriteOptions write_options;
      TrajectoryReadOptions read_options;
      if (c.format == TrajectoryFormat::kKitti) {
        write_options.kitti_times_path = dir / "times.txt";
        read_options.kitti_times_path = dir / "times.txt";
      }
      WriteTrajectory(original, dir / c.name, TrajectoryFormat::kAuto, write_options);
      const TrajectoryFile file = ReadTrajectoryFile(dir / c.name, TrajectoryFormat::kAuto, read_options);
      EXPECT_EQ(file.format, c.format);
      EXPECT_TRUE(file.warnings.empty());
      testing_util::ExpectSameTrajectory(original, file.trajectory);
    }
  }
}

TEST(TrajectoryFileTest, ExplicitFormatOverridesTheName) {
  const Trajectory original = testing_util::RandomTrajectory(10, false, 41);
  testing::TempDir dir;
  WriteTrajectory(original, dir / "poses.dat", TrajectoryFormat::kCsv);
  testing_util::ExpectSameTrajectory(original, ReadTrajectory(dir / "poses.dat", TrajectoryFormat::kCsv));
}

TEST(TrajectoryFileTest, KittiWithoutTimesIsStampedByIndex) {
  testing::TempDir dir;
  testing::WriteFile(dir / "00.txt", "1 0 0 1 0 1 0 2 0 0 1 3\n1 0 0 1 0 1 0 2 0 0 1 4\n1 0 0 1 0 1 0 2 0 0 1 5\n");
  const Trajectory t = ReadTrajectory(dir / "00.txt");
  EXPECT_EQ(t.stamps_s(), (std::vector<double>{0.0, 1.0, 2.0}));
}

TEST(TrajectoryFileTest, MrptStepStampsOption) {
  testing::TempDir dir;
  testing::WriteFile(dir / "log_estimated_path.txt", "0 0 0 0\n1 1 0 0\n");
  TrajectoryReadOptions options;
  options.mrpt_step_stamps_s = {100.0, 100.5};
  EXPECT_EQ(ReadTrajectory(dir / "log_estimated_path.txt", TrajectoryFormat::kAuto, options).stamps_s(),
            (std::vector<double>{100.0, 100.5}));
}

TEST(TrajectoryFileTest, OptionsForAnotherFormatAreRefused) {
  testing::TempDir dir;
  testing::WriteFile(dir / "a.tum", "1.0 1 2 3 0 0 0 1\n");
  TrajectoryReadOptions options;
  options.kitti_times_path = dir / "times.txt";
  ExpectInputError([&] { ReadTrajectory(dir / "a.tum", TrajectoryFormat::kAuto, options); },
                   {"a.tum", "kitti_times_path", "read as tum"});
  options = {};
  options.mrpt_step_stamps_s = {1.0};
  ExpectInputError([&] { ReadTrajectory(dir / "a.tum", TrajectoryFormat::kTum, options); },
                   {"a.tum", "mrpt_step_stamps_s"});
}

TEST(TrajectoryFileTest, CarmenWarningsReachTheCaller) {
  SLAMSWEEP_REQUIRE_SHARED(path, "datasets/orebro/orebro-corrected.log.gz");
  const TrajectoryFile file = ReadTrajectoryFile(path);
  EXPECT_EQ(file.format, TrajectoryFormat::kCarmen);
  EXPECT_EQ(file.trajectory.size(), 237u);
  ASSERT_EQ(file.warnings.size(), 1u);
  EXPECT_THAT(file.warnings[0], HasSubstr("orebro-corrected.log.gz"));
}

TEST(TrajectoryFileTest, ReadsTheSharedTumReference) {
  SLAMSWEEP_REQUIRE_SHARED(path, "reference/trajectories/intel_gmapping.tum");
  EXPECT_EQ(ReadTrajectory(path).size(), 639u);  // README: "639 poses"
}

TEST(TrajectoryFileTest, BadInputIsAnInputErrorNamingTheFile) {
  testing::TempDir dir;
  testing::WriteFile(dir / "empty.tum", "");
  ExpectInputError([&] { ReadTrajectory(dir / "empty.tum"); }, {"empty.tum", "no poses"});
  testing::WriteFile(dir / "cut.txt", "1.0 1 2 3 0 0 0 1\n2.0 1 2 3 0 0 0\n");
  ExpectInputError([&] { ReadTrajectory(dir / "cut.txt"); }, {"cut.txt:2"});
  ExpectInputError([&] { ReadTrajectory(dir / "missing.tum"); }, {"missing.tum", "no such file"});
  ExpectInputError([&] { WriteTrajectory(testing_util::RandomTrajectory(2, true, 1), dir / "x.unknown"); },
                   {"x.unknown", "cannot tell"});
  ExpectInputError([&] { WriteTrajectory(testing_util::RandomTrajectory(2, true, 1), dir / "x.log.gz"); },
                   {"x.log.gz", "gzip"});
  ExpectInputError([&] { WriteTrajectory(testing_util::RandomTrajectory(2, false, 1), dir / "3d.log"); },
                   {"not planar"});
  EXPECT_FALSE(std::filesystem::exists(dir / "3d.log")) << "a refused write must not leave a file behind";
  ExpectInputError([&] { WriteTrajectory(testing_util::RandomTrajectory(2, true, 1), dir / "no" / "such" / "a.tum"); },
                   {"a.tum", "cannot open"});
  TrajectoryReadOptions options;
  options.carmen.record_order_period_s = -1.0;
  testing::WriteFile(dir / "a.log", "FLASER 0 1 2 3 1 2 3 4 h 4\n");
  ExpectInputError([&] { ReadTrajectory(dir / "a.log", TrajectoryFormat::kCarmen, options); },
                   {"record_order_period_s"});
}

}  // namespace
}  // namespace slamsweep::evaluator
