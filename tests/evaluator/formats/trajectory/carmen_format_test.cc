#include "evaluator/formats/trajectory/carmen_format.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "evaluator/core/text_file.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "tests/evaluator/formats/trajectory/trajectory_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;
using testing_util::ExpectInputError;

std::string Flaser(double x, double stamp_s) {
  return "FLASER 2 1.5 2.5 " + std::to_string(x) + " 0 0 " + std::to_string(x) + " 0 0 " + std::to_string(stamp_s) +
         " pippo " + std::to_string(stamp_s) + "\n";
}

TEST(CarmenFormatTest, GoodStampsAreKept) {
  const CarmenPoses poses =
      CarmenPosesFromLog(ParseCarmenLog(Flaser(0, 5.5) + Flaser(1, 5.75) + Flaser(2, 6), "a.log"), "a.log");
  EXPECT_FALSE(poses.used_record_order);
  EXPECT_TRUE(poses.warnings.empty());
  EXPECT_EQ(poses.trajectory.stamps_s(), (std::vector<double>{5.5, 5.75, 6.0}));
  EXPECT_EQ(poses.trajectory.poses()[2].position.x(), 2.0);
}

TEST(CarmenFormatTest, ConstantStampsFallBackToRecordOrder) {
  const CarmenPoses poses =
      CarmenPosesFromLog(ParseCarmenLog(Flaser(0, 0) + Flaser(1, 0) + Flaser(2, 0), "z.log"), "z.log");
  EXPECT_TRUE(poses.used_record_order);
  EXPECT_EQ(poses.trajectory.stamps_s(), (std::vector<double>{0.0, 1.0, 2.0}));
  ASSERT_EQ(poses.warnings.size(), 1u);
  EXPECT_THAT(poses.warnings[0], HasSubstr("z.log"));
  EXPECT_THAT(poses.warnings[0], HasSubstr("record order"));
  EXPECT_THAT(poses.warnings[0], HasSubstr("all 3"));
}

TEST(CarmenFormatTest, WrappedClockFallsBackToRecordOrderWithTheChosenPeriod) {
  CarmenReadOptions options;
  options.record_order_period_s = 0.5;
  const std::string log = Flaser(0, -1.82) + Flaser(1, 4294970000.0) + Flaser(2, 4294970000.5);
  const CarmenPoses poses = CarmenPosesFromLog(ParseCarmenLog(log, "w.log"), "w.log", options);
  EXPECT_TRUE(poses.used_record_order);
  EXPECT_EQ(poses.trajectory.stamps_s(), (std::vector<double>{0.0, 0.5, 1.0}));
  ASSERT_EQ(poses.warnings.size(), 1u);
  EXPECT_THAT(poses.warnings[0], HasSubstr("jumps"));
}

TEST(CarmenFormatTest, RareBackwardStepIsKeptWithANote) {
  std::string log;
  for (int i = 0; i < 200; ++i) log += Flaser(i, i == 100 ? 98.5 : i);
  const CarmenPoses poses = CarmenPosesFromLog(ParseCarmenLog(log, "b.log"), "b.log");
  EXPECT_FALSE(poses.used_record_order);
  EXPECT_EQ(poses.trajectory.stamps_s()[100], 98.5);
  ASSERT_EQ(poses.warnings.size(), 1u);
  EXPECT_THAT(poses.warnings[0], HasSubstr("b.log"));
  EXPECT_THAT(poses.warnings[0], HasSubstr("stamps kept"));
}

TEST(CarmenFormatTest, RobotLaserPosesAreUsedWhenThereIsNoFlaser) {
  const std::string robot_laser =
      "ROBOTLASER1 0 -1.5708 3.14159 0.0174533 81.9 0.01 0 1 3.5 0 0.1 0.2 0.3 7 8 0.25 0 0 0 0 0 20.5 b21 20.5\n";
  const CarmenPoses only = CarmenPosesFromLog(ParseCarmenLog(robot_laser, "r.log"), "r.log");
  ASSERT_EQ(only.trajectory.size(), 1u);
  EXPECT_TRUE(testing_util::SamePose(Pose::Planar(7, 8, 0.25), only.trajectory.poses()[0], 1e-15));
  EXPECT_EQ(only.trajectory.stamps_s()[0], 20.5);

  const CarmenPoses both = CarmenPosesFromLog(ParseCarmenLog(robot_laser + Flaser(1, 21), "r.log"), "r.log");
  ASSERT_EQ(both.trajectory.size(), 1u);
  EXPECT_EQ(both.trajectory.poses()[0].position.x(), 1.0);
  ASSERT_EQ(both.warnings.size(), 1u);
  EXPECT_THAT(both.warnings[0], HasSubstr("ROBOTLASER1 records ignored"));
}

TEST(CarmenFormatTest, LogWithoutLaserIsAnInputError) {
  ExpectInputError([] { CarmenPosesFromLog(ParseCarmenLog("ODOM 0 0 0 0 0 0 1 h 1\n", "o.log"), "o.log"); },
                   {"o.log", "no FLASER or ROBOTLASER1"});
  ExpectInputError([] { CarmenPosesFromLog(ParseCarmenLog("", "e.log"), "e.log"); }, {"e.log", "no FLASER"});
}

TEST(CarmenFormatTest, BadOptionsNameTheOption) {
  CarmenReadOptions options;
  options.record_order_period_s = 0.0;
  ExpectInputError([&] { ValidateCarmenReadOptions(options); }, {"record_order_period_s"});
  options = {};
  options.max_non_increasing_fraction = 1.5;
  ExpectInputError([&] { ValidateCarmenReadOptions(options); }, {"max_non_increasing_fraction"});
}

TEST(CarmenFormatTest, RoundTripKeepsStampsAndPoses) {
  const Trajectory original = testing_util::RandomTrajectory(300, true, 11);
  testing::TempDir dir;
  WriteCarmenPoses(original, dir / "poses.log");
  const CarmenPoses read = ReadCarmenPoses(dir / "poses.log");
  EXPECT_FALSE(read.used_record_order);
  EXPECT_TRUE(read.warnings.empty());
  testing_util::ExpectSameTrajectory(original, read.trajectory);
}

TEST(CarmenFormatTest, WriterRejects3dPoses) {
  std::ostringstream out;
  ExpectInputError([&] { WriteCarmenPoses(testing_util::RandomTrajectory(2, false, 12), out); }, {"not planar"});
}

// ---- the real logs in shared/datasets ----

struct DatasetLog {
  const char* folder;
  const char* file;
  bool broken_stamps;  // per shared/README.md
};

void PrintTo(const DatasetLog& log, std::ostream* out) { *out << log.folder; }

/// The count after `key=` (or `'key': `) in the PROVENANCE "Stats:" line, 0 when absent.
std::size_t StatsCount(const std::string& provenance, const std::string& pattern) {
  std::smatch match;
  const std::regex regex(pattern);
  if (!std::regex_search(provenance, match, regex)) return 0;
  return std::stoul(match[1].str());
}

class CarmenDatasetTest : public ::testing::TestWithParam<DatasetLog> {};

TEST_P(CarmenDatasetTest, ReadsThePoseCountOfItsProvenance) {
  const DatasetLog& param = GetParam();
  const std::string folder = std::string("datasets/") + param.folder;
  SLAMSWEEP_REQUIRE_SHARED(log_path, folder + "/" + param.file);
  SLAMSWEEP_REQUIRE_SHARED(provenance_path, folder + "/PROVENANCE.txt");
  const std::string provenance = ReadTextFile(provenance_path);
  const std::size_t flaser_count = StatsCount(provenance, "FLASER=(\\d+)");
  ASSERT_GT(flaser_count, 0u) << "no FLASER= in " << provenance_path;

  const CarmenLog log = ReadCarmenLog(log_path);
  EXPECT_EQ(log.odometry.size(), StatsCount(provenance, "ODOM=(\\d+)"));
  EXPECT_EQ(log.params.size(), StatsCount(provenance, "'PARAM': (\\d+)"));
  const std::size_t neff = log.skipped_messages.contains("NEFF") ? log.skipped_messages.at("NEFF") : 0;
  EXPECT_EQ(neff, StatsCount(provenance, "'NEFF': (\\d+)"));
  const std::size_t beams = StatsCount(provenance, "readings=\\[(\\d+)\\]");
  for (const CarmenLaserRecord& laser : log.lasers) ASSERT_EQ(laser.ranges_m.size(), beams) << "line " << laser.line;

  const CarmenPoses poses = ReadCarmenPoses(log_path);
  EXPECT_EQ(poses.trajectory.size(), flaser_count);
  if (param.broken_stamps) {
    EXPECT_TRUE(poses.used_record_order);
    ASSERT_FALSE(poses.warnings.empty());
    EXPECT_THAT(poses.warnings[0], HasSubstr(param.file));
    EXPECT_THAT(poses.warnings[0], HasSubstr("record order"));
    EXPECT_EQ(poses.trajectory.stamps_s()[10], 10.0);
  }
}

INSTANTIATE_TEST_SUITE_P(SharedLogs, CarmenDatasetTest,
                         ::testing::Values(DatasetLog{"intel", "intel-corrected.log.gz", false},
                                           DatasetLog{"fr079", "freiburg-079-corrected.log.gz", false},
                                           DatasetLog{"fr101", "freiburg-101-corrected.log.gz", false},
                                           DatasetLog{"mit-csail", "csail-corrected.log.gz", false},
                                           DatasetLog{"freiburg-campus", "freiburg-campus-corrected.log.gz", true},
                                           DatasetLog{"mit-infinite-corridor", "infinite-corridor-corrected.log.gz",
                                                      true},
                                           DatasetLog{"orebro", "orebro-corrected.log.gz", true},
                                           DatasetLog{"belgioioso", "belgioioso-corrected.log.gz", true}),
                         [](const ::testing::TestParamInfo<DatasetLog>& info) {
                           std::string name = info.param.folder;
                           for (char& c : name) {
                             if (c == '-') c = '_';
                           }
                           return name;
                         });

TEST(CarmenDatasetTest, GoodClocksAreKept) {
  for (const char* relative :
       {"datasets/fr079/freiburg-079-corrected.log.gz", "datasets/fr101/freiburg-101-corrected.log.gz"}) {
    SLAMSWEEP_REQUIRE_SHARED(path, relative);
    const CarmenPoses poses = ReadCarmenPoses(path);
    EXPECT_FALSE(poses.used_record_order) << relative;
    EXPECT_TRUE(poses.warnings.empty()) << relative;
  }
}

TEST(CarmenDatasetTest, CsailStampsWithSixDigitsAreUnusable) {
  // PROVENANCE: "timestamps in this log are printed as 1.13486e+09 (6 significant digits) -> unusable".
  SLAMSWEEP_REQUIRE_SHARED(path, "datasets/mit-csail/csail-corrected.log.gz");
  const CarmenPoses poses = ReadCarmenPoses(path);
  EXPECT_TRUE(poses.used_record_order);
  ASSERT_EQ(poses.warnings.size(), 1u);
  EXPECT_THAT(poses.warnings[0], HasSubstr("csail-corrected.log.gz"));
  EXPECT_THAT(poses.warnings[0], HasSubstr("do not increase"));
}

TEST(CarmenDatasetTest, IntelMatchesTheIndependentlyConvertedTum) {
  // reference/trajectories/intel_corrected.tum holds the same poses, converted by another tool
  // and printed with 6 decimals (stamps, positions) and 9 digits (quaternions).
  SLAMSWEEP_REQUIRE_SHARED(log_path, "datasets/intel/intel-corrected.log.gz");
  SLAMSWEEP_REQUIRE_SHARED(tum_path, "reference/trajectories/intel_corrected.tum");
  const CarmenPoses poses = ReadCarmenPoses(log_path);
  const Trajectory reference = ReadTum(tum_path);
  EXPECT_FALSE(poses.used_record_order);
  // The Intel log goes back in time 4 times (by up to 0.86 s); the stamps are kept, with a note.
  ASSERT_EQ(poses.warnings.size(), 1u);
  EXPECT_THAT(poses.warnings[0], HasSubstr("4 of 909"));
  ASSERT_EQ(poses.trajectory.size(), reference.size());
  for (std::size_t i = 0; i < reference.size(); ++i) {
    EXPECT_NEAR(poses.trajectory.stamps_s()[i], reference.stamps_s()[i], 1e-6) << i;
    EXPECT_TRUE(testing_util::SamePose(reference.poses()[i], poses.trajectory.poses()[i], 2e-6)) << i;
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
