// A bare MCAP file of a ROS 2 bag: slamsweep's own MCAP reader (records, summary, chunks, CRCs), every
// channel's messages, then the file read as a sequence (the CDR decoders and the bag's sequence).
#include <set>

#include "evaluator/formats/rosbag2/mapped_file.h"
#include "evaluator/formats/rosbag2/mcap_reader.h"
#include "evaluator/formats/rosbag2/mcap_writer.h"
#include "evaluator/formats/rosbag2/rosbag2_reader.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/rosbag2_seeds.h"
#include "tests/fuzz/seed_data.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

namespace {

/// The first messages of each channel of a real MCAP file, written again by slamsweep's writer with the
/// file's own schemas and channels: a small cut that keeps the real messages.
std::string CutMcap(const std::filesystem::path& file, std::size_t per_channel) {
  const ev::MappedFile mapped(file);
  const ev::McapReader reader(mapped.Bytes(), file.string());
  const ev::McapContents& contents = reader.Contents();
  const std::filesystem::path cut = fuzz::ScratchPath("cut.mcap");
  std::filesystem::remove(cut);
  ev::McapWriter writer(cut, contents.profile);
  std::map<std::uint16_t, std::uint16_t> schema_ids;
  for (const auto& [id, schema] : contents.schemas) {
    schema_ids[id] = writer.AddSchema(schema.name, schema.encoding, schema.data);
  }
  std::map<std::uint16_t, std::uint16_t> channel_ids;
  std::set<std::uint16_t> wanted;
  for (const auto& [id, channel] : contents.channels) {
    channel_ids[id] =
        writer.AddChannel(schema_ids[channel.schema_id], channel.topic, channel.message_encoding, channel.metadata);
    wanted.insert(id);
  }
  std::map<std::uint16_t, std::size_t> taken;
  reader.ReadMessages(wanted, [&](const ev::McapMessage& message) {
    if (taken[message.channel_id]++ < per_channel) {
      writer.AddMessage(channel_ids[message.channel_id], message.log_time_ns, message.data);
    }
  });
  writer.Finish();
  return fuzz::FileBytes(cut);
}

}  // namespace

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  for (const bool with_reference : {false, true}) {
    const fuzz::SeedBag bag =
        fuzz::WriteSeedBag(fuzz::ScratchPath("seed-bag"), ev::Rosbag2StorageKind::kMcap, 6, with_reference);
    seeds.Add(with_reference ? "simulated-with-ground-truth.mcap" : "simulated.mcap", fuzz::FileBytes(bag.split_file));
  }
  if (const auto shared = fuzz::SharedPath(seeds, fuzz::kSharedMcap)) {
    seeds.Add("nav2_turtlebot-cut.mcap", CutMcap(*shared, 3));
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = fuzz::WriteInput("input.mcap", fuzz::Bytes(data, size));
  fuzz::ExpectReadOrInputError({file}, [&] {
    const ev::McapReader reader(std::span<const std::uint8_t>(data, size), file.string());
    std::set<std::uint16_t> channels;
    for (const auto& [id, channel] : reader.Contents().channels) channels.insert(id);
    for (const auto& [id, count] : reader.Contents().message_counts) channels.insert(id);
    reader.ReadMessages(channels, [&](const ev::McapMessage& message) {
      fuzz::Require(channels.count(message.channel_id) > 0, "a message of a channel that was not asked for");
    });
  });
  fuzz::CheckSequenceRead(file, [&] { return ev::ReadRosbag2(file); });
  return 0;
}
