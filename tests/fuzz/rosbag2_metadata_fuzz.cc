// A ROS 2 bag folder's metadata.yaml: ParseRosbag2Metadata, then the folder read as a sequence, beside split
// files the seeds name (an MCAP and a .db3 of the simulated run, and both compressed whole with zstd as
// rosbag2's FILE compression writes them), so that what the metadata says about them is followed.
#include <filesystem>

#include "evaluator/formats/rosbag2/bag_metadata.h"
#include "evaluator/formats/rosbag2/compression.h"
#include "evaluator/formats/rosbag2/rosbag2_reader.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/rosbag2_seeds.h"
#include "tests/fuzz/seed_data.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

namespace {

constexpr char kFolderName[] = "fuzzbag";

std::string Zstd(const std::filesystem::path& file) {
  const std::string bytes = fuzz::FileBytes(file);
  const std::vector<std::uint8_t> compressed =
      ev::ZstdCompress(std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
  return std::string(compressed.begin(), compressed.end());
}

/// The bag folder, its split files written once per process: fuzzbag_0.mcap, fuzzbag_0.db3 and the two .zstd.
/// Returns the metadata.yaml of each storage as the writer made it.
struct Folder {
  std::filesystem::path path;
  std::string mcap_metadata;
  std::string sqlite_metadata;
};

const Folder& BagFolder() {
  static const Folder folder = [] {
    Folder made;
    made.path = fuzz::ScratchPath(kFolderName);
    std::filesystem::create_directories(made.path);
    for (const ev::Rosbag2StorageKind storage : {ev::Rosbag2StorageKind::kMcap, ev::Rosbag2StorageKind::kSqlite3}) {
      const fuzz::SeedBag bag = fuzz::WriteSeedBag(fuzz::ScratchPath("seed-bag") / kFolderName, storage, 4, true);
      const std::filesystem::path split = made.path / bag.split_file.filename();
      std::filesystem::copy_file(bag.split_file, split, std::filesystem::copy_options::overwrite_existing);
      fuzz::WriteInput(std::string(kFolderName) + "/" + split.filename().string() + ".zstd", Zstd(split));
      (storage == ev::Rosbag2StorageKind::kMcap ? made.mcap_metadata : made.sqlite_metadata) =
          fuzz::FileBytes(bag.metadata);
    }
    return made;
  }();
  return folder;
}

/// The writer's metadata with the split file compressed whole (compression_mode FILE).
std::string FileCompressed(const std::string& yaml) {
  ev::Rosbag2Metadata metadata = ev::ParseRosbag2Metadata(yaml, "metadata.yaml");
  metadata.compression_format = "zstd";
  metadata.compression_mode = "FILE";
  for (std::string& path : metadata.relative_file_paths) path += ".zstd";
  for (ev::Rosbag2FileInfo& file : metadata.files) file.path += ".zstd";
  return ev::FormatRosbag2Metadata(metadata);
}

}  // namespace

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  const Folder& folder = BagFolder();
  seeds.Add("mcap-metadata.yaml", folder.mcap_metadata);
  seeds.Add("sqlite-metadata.yaml", folder.sqlite_metadata);
  seeds.Add("mcap-file-compressed-metadata.yaml", FileCompressed(folder.mcap_metadata));
  seeds.Add("sqlite-file-compressed-metadata.yaml", FileCompressed(folder.sqlite_metadata));
  if (const auto shared = seeds.SharedFile("datasets/ros2/evo-tf-example/metadata.yaml")) {
    seeds.Add("tf_example-metadata.yaml", *shared);
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Folder& folder = BagFolder();
  const std::filesystem::path file =
      fuzz::WriteInput(std::string(kFolderName) + "/metadata.yaml", fuzz::Bytes(data, size));
  fuzz::ExpectReadOrInputError({file}, [&] { ev::ParseRosbag2Metadata(fuzz::Bytes(data, size), file); });
  // Errors name the metadata, the folder or a split file (all of them hold the folder's name).
  fuzz::CheckSequenceRead(folder.path, [&] { return ev::ReadRosbag2(folder.path); });
  return 0;
}
