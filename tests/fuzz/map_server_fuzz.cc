// ROS map_server maps: the YAML, then (after fuzz::kPartSeparator) the image it names, which the target
// writes as both map.pgm and map.png (the YAML says which is read; the decoders go by content).
#include <algorithm>
#include <string>

#include "evaluator/formats/map/map_file.h"
#include "evaluator/formats/map/map_server_format.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/seed_data.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

namespace {

/// The YAML and image WriteMapServer writes for `grid`, as one input.
std::string WrittenMap(const fuzz::Seeds& seeds, const ev::OccupancyGrid& grid, const ev::MapWriteOptions& options) {
  const std::filesystem::path folder = seeds.folder() / "written";
  std::filesystem::create_directories(folder);
  ev::WriteMapServer(grid, folder / "map.yaml", options);
  const bool pgm = options.mode == ev::MapWriteOptions::Mode::kTrinary && !options.trinary_png;
  std::string input =
      fuzz::JoinParts({fuzz::FileBytes(folder / "map.yaml"), fuzz::FileBytes(folder / (pgm ? "map.pgm" : "map.png"))});
  std::filesystem::remove_all(folder);
  return input;
}

/// A `size` x `size` cut from the middle of `grid`.
ev::OccupancyGrid Middle(const ev::OccupancyGrid& grid, int size) {
  const int width = std::min(size, grid.width);
  const int height = std::min(size, grid.height);
  const int left = (grid.width - width) / 2;
  const int top = (grid.height - height) / 2;
  ev::OccupancyGrid cut(width, height, grid.resolution_m, grid.origin);
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) cut.at(row, col) = grid.at(top + row, left + col);
  }
  return cut;
}

}  // namespace

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  const ev::OccupancyGrid grid = fuzz::SeedGrid();
  ev::MapWriteOptions options;
  seeds.Add("trinary-pgm", WrittenMap(seeds, grid, options));
  options.trinary_png = true;
  seeds.Add("trinary-png", WrittenMap(seeds, grid, options));
  options.mode = ev::MapWriteOptions::Mode::kScale;
  seeds.Add("scale-png", WrittenMap(seeds, grid, options));
  seeds.Add("raw-ascii-pgm", fuzz::JoinParts({"image: map.pgm\nresolution: 0.1\norigin: [0.0, 0.0, 0.0]\nnegate: 1\n"
                                              "occupied_thresh: 0.65\nfree_thresh: 0.196\nmode: raw\n",
                                              "P2\n# grey\n4 3\n255\n0 50 100 255\n1 2 3 4\n205 205 254 254\n"}));
  for (const char* shared : {"reference/maps/telecom_icp.yaml", "reference/maps/telecom_rbpf.yaml"}) {
    if (!seeds.SharedFile(shared)) continue;
    const ev::OccupancyGrid map = ev::ReadMap(seeds.shared() / shared);
    seeds.Add(std::filesystem::path(shared).stem().string() + "-cut", WrittenMap(seeds, Middle(map, 48), {}));
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto parts = fuzz::SplitParts(fuzz::Bytes(data, size), 2);
  const std::filesystem::path yaml = fuzz::WriteInput("map.yaml", parts[0]);
  const std::filesystem::path pgm = fuzz::WriteInput("map.pgm", parts[1]);
  const std::filesystem::path png = fuzz::WriteInput("map.png", parts[1]);
  fuzz::ExpectReadOrInputError({yaml, pgm, png}, [&] { ev::ReadMap(yaml); });
  return 0;
}
