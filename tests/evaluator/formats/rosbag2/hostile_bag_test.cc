// ROS 2 bags made to hurt: SQL in a .db3 that would run for ever, split files outside the bag folder, an MCAP
// chunk that claims a terabyte. Each is refused at once with an InputError naming the file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <fstream>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/rosbag2/mcap_reader.h"
#include "evaluator/formats/rosbag2/rosbag2_reader.h"
#include "evaluator/formats/rosbag2/sqlite_bag.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

/// A database of `statements` at `path`.
void MakeDatabase(const std::filesystem::path& path, std::initializer_list<const char*> statements) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  for (const char* statement : statements) {
    ASSERT_EQ(sqlite3_exec(db, statement, nullptr, nullptr, nullptr), SQLITE_OK) << statement;
  }
  sqlite3_close(db);
}

std::vector<std::uint8_t> FileBytesOf(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {});
}

TEST(HostileBagTest, AMessagesViewOfAnEndlessQueryIsRefusedNotRun) {
  const testing::TempDir dir;
  const std::filesystem::path path = dir / "endless.db3";
  MakeDatabase(path, {"CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT, type TEXT, serialization_format TEXT)",
                      "INSERT INTO topics VALUES (1, '/scan', 'sensor_msgs/msg/LaserScan', 'cdr')",
                      "CREATE VIEW messages AS WITH RECURSIVE n(i) AS (SELECT 1 UNION ALL SELECT i + 1 FROM n) "
                      "SELECT i AS id, 1 AS topic_id, i AS timestamp, zeroblob(1000) AS data FROM n"});
  // Before views were turned off, both read the view for ever.
  EXPECT_THAT([&] { SqliteBag::Open(path); }, ThrowsMessage<InputError>(HasSubstr("endless.db3")));
  EXPECT_THAT([&] { SqliteBag::FromBytes(FileBytesOf(path), "inflated.db3"); },
              ThrowsMessage<InputError>(HasSubstr("inflated.db3")));
}

TEST(HostileBagTest, ASplitFileOutsideTheBagFolderIsRefused) {
  const testing::TempDir dir;
  const std::filesystem::path folder = dir / "bag";
  std::filesystem::create_directories(folder);
  std::ofstream(dir / "outside.mcap") << "not read";
  for (const char* named : {"/etc/hostname", "../outside.mcap", "sub/../../outside.mcap"}) {
    std::ofstream(folder / "metadata.yaml")
        << "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: mcap\n"
        << "  relative_file_paths:\n    - \"" << named << "\"\n";
    EXPECT_THAT([&] { Rosbag2Bag bag(folder); },
                ThrowsMessage<InputError>(AllOf(HasSubstr(named), HasSubstr("not a file inside the bag folder"))))
        << named;
  }
}

TEST(HostileBagTest, AChunkClaimingATerabyteIsRefusedBeforeInflating) {
  // Magic, Header (profile ros2), a zstd Chunk stating 2^40 bytes inflated around a 9-byte frame, DataEnd, Footer.
  const auto record = [](std::uint8_t opcode, const std::vector<std::uint8_t>& body) {
    std::vector<std::uint8_t> out{opcode};
    for (int i = 0; i < 8; ++i) out.push_back(static_cast<std::uint8_t>(std::uint64_t{body.size()} >> (8 * i)));
    out.insert(out.end(), body.begin(), body.end());
    return out;
  };
  const auto number = [](std::vector<std::uint8_t>& out, std::uint64_t value, int bytes) {
    for (int i = 0; i < bytes; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
  };
  const std::vector<std::uint8_t> magic = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
  const std::vector<std::uint8_t> frame = {0x28, 0xb5, 0x2f, 0xfd, 0x00, 0x00, 0x01, 0x00, 0x00};
  std::vector<std::uint8_t> header;
  number(header, 4, 4);
  header.insert(header.end(), {'r', 'o', 's', '2'});
  number(header, 0, 4);
  std::vector<std::uint8_t> chunk;
  number(chunk, 0, 8);
  number(chunk, 0, 8);
  number(chunk, std::uint64_t{1} << 40, 8);
  number(chunk, 0, 4);
  number(chunk, 4, 4);
  chunk.insert(chunk.end(), {'z', 's', 't', 'd'});
  number(chunk, frame.size(), 8);
  chunk.insert(chunk.end(), frame.begin(), frame.end());
  std::vector<std::uint8_t> file = magic;
  for (const auto& part : {record(0x01, header), record(0x06, chunk), record(0x0f, {0, 0, 0, 0}),
                           record(0x02, std::vector<std::uint8_t>(20, 0)), magic}) {
    file.insert(file.end(), part.begin(), part.end());
  }
  EXPECT_THAT([&] { McapReader(file, "terabyte.mcap"); },
              ThrowsMessage<InputError>(AllOf(HasSubstr("terabyte.mcap: Chunk record at byte"),
                                              HasSubstr("states 1099511627776 bytes"), HasSubstr("the cap"))));
}

}  // namespace
}  // namespace slamsweep::evaluator
