// A bare .db3 file of a ROS 2 bag (rosbag2's sqlite3 storage): SQLite on the bytes as slamsweep opens an
// inflated file (SqliteBag::FromBytes), every topic's messages, then the file read as a sequence.
#include <set>

#include "evaluator/formats/rosbag2/ros2_messages.h"
#include "evaluator/formats/rosbag2/rosbag2_reader.h"
#include "evaluator/formats/rosbag2/sqlite_bag.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/rosbag2_seeds.h"
#include "tests/fuzz/seed_data.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

namespace {

/// The first messages of each topic of a real .db3, written again by slamsweep's sqlite3 writer.
std::string CutDb3(const std::filesystem::path& file, std::size_t per_topic) {
  const std::filesystem::path cut = fuzz::ScratchPath("cut.db3");
  std::filesystem::remove(cut);
  {
    ev::SqliteBagWriter writer(cut, "humble");
    std::map<std::string, std::int64_t> ids;
    std::int64_t stamp_ns = 1'000'000'000;
    for (const fuzz::SeedMessage& message : fuzz::FirstMessages(file, per_topic)) {
      if (ids.count(message.topic) == 0) ids[message.topic] = writer.AddTopic(message.topic, message.type, "");
      writer.AddMessage(ids[message.topic], stamp_ns += 1000, message.data);
    }
    writer.Finish(5, "");
  }
  return fuzz::FileBytes(cut);
}

}  // namespace

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  for (const bool with_reference : {false, true}) {
    const fuzz::SeedBag bag =
        fuzz::WriteSeedBag(fuzz::ScratchPath("seed-bag"), ev::Rosbag2StorageKind::kSqlite3, 4, with_reference);
    seeds.Add(with_reference ? "simulated-with-ground-truth.db3" : "simulated.db3", fuzz::FileBytes(bag.split_file));
  }
  if (const auto shared = fuzz::SharedPath(seeds, fuzz::kSharedDb3)) {
    seeds.Add("tf_example-cut.db3", CutDb3(*shared, 3));
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = fuzz::WriteInput("input.db3", fuzz::Bytes(data, size));
  fuzz::ExpectReadOrInputError({file}, [&] {
    const ev::SqliteBag bag = ev::SqliteBag::FromBytes(std::vector<std::uint8_t>(data, data + size), file.string());
    std::set<std::int64_t> ids;
    for (const ev::SqliteTopic& topic : bag.Topics()) ids.insert(topic.id);
    bag.ReadMessages(ids, [&](std::int64_t, std::int64_t, std::span<const std::uint8_t> message) {
      // A blob lies in the database's pages: never more bytes than the file has.
      fuzz::Require(message.size() <= size, "a message larger than the database file");
    });
  });
  fuzz::CheckSequenceRead(file, [&] { return ev::ReadRosbag2(file); });
  return 0;
}
