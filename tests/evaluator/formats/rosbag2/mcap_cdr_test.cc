// slamsweep's own CDR and MCAP code on bytes made by hand, and damaged MCAP files: every error names the file
// and the record (or the message) and never crashes or hangs.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/rosbag2/cdr.h"
#include "evaluator/formats/rosbag2/mapped_file.h"
#include "evaluator/formats/rosbag2/mcap_reader.h"
#include "evaluator/formats/rosbag2/mcap_writer.h"
#include "evaluator/formats/rosbag2/ros2_messages.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(CdrTest, AlignsFromTheByteAfterTheHeaderInBothByteOrders) {
  // int32 1, then a float64 2.5 at offset 8 of the body (4 bytes of padding), then "ab".
  const std::vector<std::uint8_t> little = {0x00, 0x01, 0x00, 0x00, 1,    0,    0, 0, 0, 0, 0,   0,   0, 0,
                                            0,    0,    0,    0,    0x04, 0x40, 3, 0, 0, 0, 'a', 'b', 0};
  CdrReader reader(little, "little");
  EXPECT_FALSE(reader.BigEndian());
  EXPECT_EQ(reader.Int32(), 1);
  EXPECT_EQ(reader.Float64(), 2.5);
  EXPECT_EQ(reader.String(), "ab");
  const std::vector<std::uint8_t> big = {0x00, 0x00, 0x00, 0x00, 0, 0, 0, 1, 0, 0, 0,   0,   0x40, 0x04,
                                         0,    0,    0,    0,    0, 0, 0, 0, 0, 3, 'a', 'b', 0};
  CdrReader big_reader(big, "big");
  EXPECT_TRUE(big_reader.BigEndian());
  EXPECT_EQ(big_reader.Int32(), 1);
  EXPECT_EQ(big_reader.Float64(), 2.5);
  EXPECT_EQ(big_reader.String(), "ab");
}

TEST(CdrTest, WriterAndReaderAgree) {
  CdrWriter writer;
  writer.Int32(-7);
  writer.String("odom");
  writer.Float64(1.25);
  writer.Float32Sequence({1.5f, 2.5f});
  EXPECT_EQ(writer.Bytes().size(), 4u + 4 + 4 + 5 + 3 + 8 + 4 + 8);
  CdrReader reader(writer.Bytes(), "written");
  EXPECT_EQ(reader.Int32(), -7);
  EXPECT_EQ(reader.String(), "odom");
  EXPECT_EQ(reader.Float64(), 1.25);
  EXPECT_EQ(reader.Float32Sequence(), (std::vector<float>{1.5f, 2.5f}));
}

TEST(CdrTest, BadMessagesNameWhereAndWhat) {
  const std::vector<std::uint8_t> xcdr2 = {0x00, 0x07, 0x00, 0x00, 1, 0, 0, 0};
  EXPECT_THAT([&] { CdrReader(xcdr2, "bag.db3: topic '/scan' message 3"); },
              ThrowsMessage<InputError>(AllOf(HasSubstr("bag.db3: topic '/scan' message 3"), HasSubstr("XCDR2"))));
  const std::vector<std::uint8_t> short_header = {0x00};
  EXPECT_THAT([&] { CdrReader(short_header, "m"); }, ThrowsMessage<InputError>(HasSubstr("shorter than its 4-byte")));
  const std::vector<std::uint8_t> huge_sequence = {0x00, 0x01, 0x00, 0x00, 0xff, 0xff, 0xff, 0x7f, 0, 0};
  CdrReader sequence(huge_sequence, "m");
  EXPECT_THAT([&] { sequence.Float32Sequence(); }, ThrowsMessage<InputError>(HasSubstr("does not fit")));
  const std::vector<std::uint8_t> cut_double = {0x00, 0x01, 0x00, 0x00, 0, 0, 0, 0, 1, 2};
  CdrReader cut(cut_double, "m");
  EXPECT_THAT([&] { cut.Float64(); }, ThrowsMessage<InputError>(HasSubstr("truncated CDR message: float64")));
}

TEST(Ros2MessagesTest, EncodedMessagesDecodeToTheirValues) {
  BagScan scan;
  scan.stamp_s = 12.5;
  scan.frame_id = "laser";
  scan.angle_min_rad = -1.5f;
  scan.angle_increment_rad = 0.5f;
  scan.range_max_m = 30.0f;
  scan.ranges_m = {1.0f, 2.0f, 3.0f};
  const BagScan decoded = DecodeLaserScan(EncodeLaserScan(scan), 13.0, "scan");
  EXPECT_EQ(decoded.stamp_s, 12.5);
  EXPECT_EQ(decoded.record_s, 13.0);
  EXPECT_EQ(decoded.frame_id, "laser");
  EXPECT_EQ(decoded.angle_min_rad, -1.5f);
  EXPECT_EQ(decoded.angle_increment_rad, 0.5f);
  EXPECT_EQ(decoded.range_max_m, 30.0f);
  EXPECT_EQ(decoded.ranges_m, scan.ranges_m);
  const BagStampedPose odometry{7.25, 7.25, "odom", "base_link", BagPose{1, 2, 0, 0, 0, 0.6, 0.8}};
  const BagStampedPose back = DecodeStampedPose(BagMessageKind::kOdometry, EncodeOdometry(odometry), 7.25, "odom");
  EXPECT_EQ(back.child_frame_id, "base_link");
  EXPECT_EQ(back.pose.qz, 0.6);
  std::vector<BagStampedPose> transforms;
  DecodeTfMessage(EncodeTfMessage({odometry, odometry}), 7.25, "tf", transforms);
  ASSERT_EQ(transforms.size(), 2u);
  EXPECT_EQ(transforms[1].pose.x_m, 1.0);
  EXPECT_THAT(
      Ros2MessageDefinition(BagMessageKind::kTfMessage),
      AllOf(::testing::StartsWith("geometry_msgs/TransformStamped[] transforms\n"),
            HasSubstr("\nMSG: geometry_msgs/TransformStamped\n"), HasSubstr("\nMSG: builtin_interfaces/Time\n")));
}

std::vector<std::uint8_t> ReadBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {});
}

void WriteBytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

class McapFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    McapWriter writer(path_, "ros2");
    const std::uint16_t schema = writer.AddSchema("nav_msgs/msg/Odometry", "ros2msg", "x");
    const std::uint16_t channel = writer.AddChannel(schema, "/odom", "cdr", {{"offered_qos_profiles", ""}});
    for (int i = 0; i < 3000; ++i) {
      const BagStampedPose pose{i * 0.1, i * 0.1, "odom", "base_link", BagPose{double(i), 0, 0, 0, 0, 0, 1}};
      writer.AddMessage(channel, static_cast<std::uint64_t>(i) * 100000000, EncodeOdometry(pose));
    }
    writer.Finish();
    bytes_ = ReadBytes(path_);
  }

  /// Reads every message of `path` and returns how many.
  static std::size_t CountMessages(const std::filesystem::path& path) {
    const MappedFile file(path);
    const McapReader reader(file.Bytes(), path.string());
    std::size_t count = 0;
    reader.ReadMessages({1}, [&](const McapMessage&) { ++count; });
    return count;
  }

  std::size_t ChunkOffset() const {
    for (std::size_t i = 8; i + 9 < bytes_.size();) {
      if (bytes_[i] == 0x06) return i;
      std::uint64_t length = 0;
      for (int b = 0; b < 8; ++b) length |= std::uint64_t{bytes_[i + 1 + b]} << (8 * b);
      i += 9 + length;
    }
    return 0;
  }

  testing::TempDir dir_;
  std::filesystem::path path_ = dir_ / "bag.mcap";
  std::vector<std::uint8_t> bytes_;
};

TEST_F(McapFileTest, IndexedFileReadsThroughItsSummary) {
  const MappedFile file(path_);
  const McapReader reader(file.Bytes(), path_.string());
  EXPECT_TRUE(reader.Contents().indexed);
  EXPECT_EQ(reader.Contents().profile, "ros2");
  EXPECT_EQ(reader.Contents().message_count, 3000u);
  EXPECT_EQ(reader.Contents().channels.at(1).topic, "/odom");
  EXPECT_EQ(CountMessages(path_), 3000u);
}

TEST_F(McapFileTest, ADamagedSummaryIsReadAroundByStreaming) {
  std::vector<std::uint8_t> damaged = bytes_;
  damaged[damaged.size() - 8 - 29 - 40] ^= 0xff;  // inside the summary: its CRC no longer matches
  WriteBytes(path_, damaged);
  const MappedFile file(path_);
  const McapReader reader(file.Bytes(), path_.string());
  EXPECT_FALSE(reader.Contents().indexed);
  ASSERT_EQ(reader.Contents().notes.size(), 1u);
  EXPECT_THAT(reader.Contents().notes[0],
              AllOf(HasSubstr("summary section is damaged (wrong CRC"), HasSubstr("read from its start")));
  EXPECT_EQ(reader.Contents().message_count, 3000u);
  EXPECT_EQ(CountMessages(path_), 3000u);
}

TEST_F(McapFileTest, AChunkWithAWrongCrcIsAnErrorNamingIt) {
  std::vector<std::uint8_t> damaged = bytes_;
  const std::size_t chunk = ChunkOffset();
  ASSERT_GT(chunk, 0u);
  damaged[chunk + 200] ^= 0x01;  // a byte of its first message's data
  WriteBytes(path_, damaged);
  EXPECT_THAT(
      [&] { CountMessages(path_); },
      ThrowsMessage<InputError>(AllOf(HasSubstr(path_.string() + ": Chunk record at byte " + std::to_string(chunk)),
                                      HasSubstr("wrong CRC"))));
}

TEST_F(McapFileTest, AFileCutInItsSummaryIsReadFromItsStart) {
  WriteBytes(path_, std::vector<std::uint8_t>(bytes_.begin(), bytes_.end() - 100));
  const MappedFile file(path_);
  const McapReader reader(file.Bytes(), path_.string());
  EXPECT_FALSE(reader.Contents().indexed);
  ASSERT_EQ(reader.Contents().notes.size(), 1u);
  EXPECT_THAT(reader.Contents().notes[0], HasSubstr("does not end with the MCAP footer"));
  EXPECT_EQ(CountMessages(path_), 3000u);
}

TEST_F(McapFileTest, ATruncatedFileIsAnErrorNamingTheRecord) {
  for (const std::size_t keep : {bytes_.size() / 2, std::size_t{20}, std::size_t{8}}) {
    WriteBytes(path_, std::vector<std::uint8_t>(bytes_.begin(), bytes_.begin() + static_cast<std::ptrdiff_t>(keep)));
    EXPECT_THAT([&] { CountMessages(path_); },
                ThrowsMessage<InputError>(AllOf(HasSubstr(path_.string()), HasSubstr("truncated"))))
        << "kept " << keep;
  }
}

TEST_F(McapFileTest, NotAnMcapFile) {
  WriteBytes(path_, {'#', 'R', 'O', 'S', 'B', 'A', 'G', ' ', 'V', '2'});
  EXPECT_THAT([&] { CountMessages(path_); }, ThrowsMessage<InputError>(HasSubstr("not an MCAP file")));
}

}  // namespace
}  // namespace slamsweep::evaluator
