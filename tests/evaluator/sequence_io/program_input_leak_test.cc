// A SLAM program must never be handed the answer. Every format slamsweep writes for a program is
// written from a RobotLog of a sequence whose reference differs from its odometry at every scan,
// and no reference coordinate may appear anywhere in the written file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "evaluator/formats/trajectory/tum_format.h"
#include "evaluator/sequence_io/robot_log_file.h"
#include "evaluator/sequence_io/sequence_file.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

constexpr double kTolerance = 1e-6;

// The type itself keeps the truth out: no conversion from a Sequence, no field for a reference.
static_assert(!std::is_convertible_v<Sequence, RobotLog>);
static_assert(
    !std::is_invocable_v<decltype(&WriteRobotLog), const Sequence&, const std::filesystem::path&, SequenceWriteFormat>);

/// 40 scans whose reference poses are hundreds of metres and about a radian away from the odometry,
/// with ranges and stamps that cannot coincide with either (so a match can only be a leak).
Sequence DivergingSequence(int beams, const Pose& mount) {
  Sequence sequence;
  sequence.name = "diverging";
  Trajectory reference;
  for (int i = 0; i < 40; ++i) {
    LaserScan scan;
    scan.stamp_s = 1000.5 + 0.25 * i;
    scan.angle_min_rad = beams == 181 ? -std::numbers::pi / 2 : -std::numbers::pi;
    scan.angle_increment_rad = beams == 181 ? std::numbers::pi / 180 : 2 * std::numbers::pi / beams;
    scan.range_max_m = 30.0;
    scan.sensor_pose_on_robot = mount;
    scan.ranges_m.assign(static_cast<std::size_t>(beams), 7.5f);
    scan.ranges_m[3] = 12.25f;
    sequence.scans.push_back(scan);
    sequence.odometry.Add(scan.stamp_s, Pose::Planar(3.0 + 0.1 * i, -2.0 + 0.05 * i, -0.6 + 0.01 * i));
    reference.Add(scan.stamp_s, Pose::Planar(512.345678 + 0.2 * i, 733.456789 - 0.3 * i, 1.4321 + 0.003 * i));
  }
  sequence.reference = reference;
  return sequence;
}

std::vector<double> NumbersIn(const std::string& text) {
  std::vector<double> numbers;
  std::istringstream words(text);
  std::string word;
  while (words >> word) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error == std::errc() && end == word.data() + word.size()) numbers.push_back(value);
  }
  return numbers;
}

/// Every reference coordinate (x, y and yaw of every pose) that a number of `numbers` matches.
std::vector<std::string> ReferenceValuesIn(const std::vector<double>& numbers, const Trajectory& reference) {
  std::vector<std::string> found;
  for (const Pose& pose : reference.poses()) {
    for (double coordinate : {pose.position.x(), pose.position.y(), pose.Yaw()}) {
      for (double number : numbers) {
        if (std::abs(number - coordinate) < kTolerance) found.push_back(std::to_string(coordinate));
      }
    }
  }
  return found;
}

std::string ReadBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(ProgramInputLeakTest, CarmenFlaserHoldsOnlyOdometry) {
  const Sequence sequence = DivergingSequence(181, Pose());
  const std::string text = FormatCarmenLog(RobotLogOf(sequence));
  ASSERT_THAT(text, ::testing::HasSubstr("FLASER 181 "));
  EXPECT_THAT(ReferenceValuesIn(NumbersIn(text), *sequence.reference), ::testing::IsEmpty());
  // Positive control: the odometry is there (a writer that wrote nothing would pass the check above).
  EXPECT_THAT(ReferenceValuesIn(NumbersIn(text), sequence.odometry), ::testing::Not(::testing::IsEmpty()));
}

TEST(ProgramInputLeakTest, CarmenRobotLaserHoldsOnlyOdometry) {
  const Sequence sequence = DivergingSequence(360, Pose::Planar(0.25, -0.1, 0.05));
  const std::string text = FormatCarmenLog(RobotLogOf(sequence));
  ASSERT_THAT(text, ::testing::HasSubstr("ROBOTLASER1 "));
  EXPECT_THAT(ReferenceValuesIn(NumbersIn(text), *sequence.reference), ::testing::IsEmpty());
  EXPECT_THAT(ReferenceValuesIn(NumbersIn(text), sequence.odometry), ::testing::Not(::testing::IsEmpty()));
}

TEST(ProgramInputLeakTest, TumIsTheOdometry) {
  testing::TempDir dir;
  const Sequence sequence = DivergingSequence(181, Pose());
  WriteRobotLog(RobotLogOf(sequence), dir / "input.tum", SequenceWriteFormat::kTum);
  const std::string text = ReadBytes(dir / "input.tum");
  // TUM stores a quaternion, not a yaw: also compare the poses read back.
  EXPECT_THAT(ReferenceValuesIn(NumbersIn(text), *sequence.reference), ::testing::IsEmpty());
  const Trajectory read = ReadTum(dir / "input.tum");
  ASSERT_EQ(read.size(), sequence.odometry.size());
  for (std::size_t i = 0; i < read.size(); ++i) {
    EXPECT_GT((read.poses()[i].position - sequence.reference->poses()[i].position).norm(), 1.0) << i;
    EXPECT_LT((read.poses()[i].position - sequence.odometry.poses()[i].position).norm(), kTolerance) << i;
  }
}

TEST(ProgramInputLeakTest, RawlogHoldsNoReferenceBytes) {
  if (!RawlogSupported()) SLAMSWEEP_SKIP_OR_FAIL_IN_CI("MRPT rawlog support not built: nothing to check");
  testing::TempDir dir;
  const Sequence sequence = DivergingSequence(181, Pose());
  WriteRobotLog(RobotLogOf(sequence), dir / "input.rawlog", SequenceWriteFormat::kRawlog);
  // MRPT serialises poses as doubles or floats, and gzips the stream: decode it with MRPT's own
  // reader and check every pose a program could reconstruct.
  const Sequence read = ReadSequence(dir / "input.rawlog");
  EXPECT_FALSE(read.reference.has_value());
  ASSERT_EQ(read.odometry.size(), sequence.odometry.size());
  for (std::size_t i = 0; i < read.odometry.size(); ++i) {
    EXPECT_GT((read.odometry.poses()[i].position - sequence.reference->poses()[i].position).norm(), 1.0) << i;
    EXPECT_LT((read.odometry.poses()[i].position - sequence.odometry.poses()[i].position).norm(), 1e-4) << i;
  }
  // And the raw bytes of the uncompressed stream: no reference coordinate as a double or a float.
  testing::TempDir raw;
  const std::string command =
      "gzip -dc '" + (dir / "input.rawlog").string() + "' > '" + (raw / "stream").string() + "'";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const std::string bytes = ReadBytes(raw / "stream");
  ASSERT_GT(bytes.size(), 1000u);
  for (const Pose& pose : sequence.reference->poses()) {
    for (double coordinate : {pose.position.x(), pose.position.y(), pose.Yaw()}) {
      char as_double[sizeof(double)];
      std::memcpy(as_double, &coordinate, sizeof coordinate);
      const float single = static_cast<float>(coordinate);
      char as_float[sizeof(float)];
      std::memcpy(as_float, &single, sizeof single);
      EXPECT_EQ(bytes.find(std::string(as_double, sizeof as_double)), std::string::npos) << coordinate;
      EXPECT_EQ(bytes.find(std::string(as_float, sizeof as_float)), std::string::npos) << coordinate;
    }
  }
}

TEST(ProgramInputLeakTest, ARawRobotLogReadsBackWithoutAReference) {
  testing::TempDir dir;
  const Sequence sequence = DivergingSequence(181, Pose());
  WriteRobotLog(RobotLogOf(sequence), dir / "input.log", SequenceWriteFormat::kCarmen);
  const Sequence read = ReadSequence(dir / "input.log");
  EXPECT_FALSE(read.reference.has_value()) << "slamsweep's program input would claim its odometry as ground truth";
  ASSERT_EQ(read.odometry.size(), 40u);
  EXPECT_LT((read.odometry.poses()[5].position - sequence.odometry.poses()[5].position).norm(), kTolerance);
}

}  // namespace
}  // namespace slamsweep::evaluator
