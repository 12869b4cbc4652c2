// The MRPT and ROS format modules are loaded when, and only when, a file in their format is read or
// written, and their errors reach the caller as they did when the readers were linked in. A program
// of its own: whether a library is mapped depends on what the process did before.
#include "evaluator/sequence_io/format_modules.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <iterator>
#include <numbers>
#include <string>

#include "evaluator/core/input_error.h"
#include "evaluator/sequence_io/robot_log_file.h"
#include "evaluator/sequence_io/sequence_file.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

/// Whether a shared object whose path contains `name` is mapped into this process.
bool Mapped(const std::string& name) {
  std::ifstream maps("/proc/self/maps");
  const std::string text((std::istreambuf_iterator<char>(maps)), std::istreambuf_iterator<char>());
  return text.find(name) != std::string::npos;
}

RobotLog SmallLog() {
  RobotLog log;
  log.name = "small";
  for (int i = 0; i < 3; ++i) {
    LaserScan scan;
    scan.stamp_s = 10.0 + i;
    scan.angle_min_rad = -std::numbers::pi / 2;
    scan.angle_increment_rad = std::numbers::pi / 180;
    scan.range_max_m = 30.0;
    scan.ranges_m.assign(181, 2.5f + 0.1f * static_cast<float>(i));
    log.scans.push_back(scan);
    log.odometry.Add(scan.stamp_s, Pose::Planar(0.5 * i, 0.0, 0.1 * i));
  }
  return log;
}

std::string InputErrorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no InputError)";
}

TEST(FormatModulesTest, MrptIsLoadedOnlyForRawlogsAndRosOnlyForBags) {
  testing::TempDir dir;
  WriteRobotLog(SmallLog(), dir / "small.log", SequenceWriteFormat::kCarmen);
  EXPECT_EQ(ReadSequence(dir / "small.log").scans.size(), 3u);
  EXPECT_FALSE(Mapped("slamsweep-rawlog.so"));
  EXPECT_FALSE(Mapped("libmrpt"));
  EXPECT_FALSE(Mapped("slamsweep-rosbag.so"));
  EXPECT_FALSE(Mapped("librosbag"));

#ifdef SLAMSWEEP_HAVE_MRPT
  WriteRobotLog(SmallLog(), dir / "small.rawlog", SequenceWriteFormat::kRawlog);
  EXPECT_TRUE(Mapped("slamsweep-rawlog.so"));
  EXPECT_TRUE(Mapped("libmrpt-obs"));
  EXPECT_FALSE(Mapped("librosbag"));
  const Sequence read = ReadSequence(dir / "small.rawlog");
  ASSERT_EQ(read.scans.size(), 3u);
  EXPECT_EQ(read.scans[2].ranges_m[90], 2.7f);
#endif
#ifdef SLAMSWEEP_HAVE_ROSBAG
  testing::WriteFile(dir / "broken.bag", "#ROSBAG V2.0\nnot a bag after all");
  const std::string message = InputErrorOf([&] { ReadSequence(dir / "broken.bag"); });
  EXPECT_THAT(message, HasSubstr("broken.bag"));  // the reader's InputError, thrown again on this side
  EXPECT_TRUE(Mapped("slamsweep-rosbag.so"));
  EXPECT_TRUE(Mapped("librosbag_storage"));
#endif
}

TEST(FormatModulesTest, AReaderErrorCrossesTheModuleAsAnInputError) {
#ifndef SLAMSWEEP_HAVE_MRPT
  SLAMSWEEP_SKIP_OR_FAIL_IN_CI("MRPT rawlog module not built (Debian: libmrpt-obs-dev, scripts/install-deps.sh)");
#else
  testing::TempDir dir;
  testing::WriteFile(dir / "garbage.rawlog", "this is no MRPT serialization");
  const std::string message = InputErrorOf([&] { ReadSequence(dir / "garbage.rawlog"); });
  EXPECT_THAT(message, HasSubstr("garbage.rawlog"));
#endif
}

}  // namespace
}  // namespace slamsweep::evaluator
