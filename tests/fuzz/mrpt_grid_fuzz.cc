// MRPT grid bitmaps: the limits file (grid_limits.txt), then (after fuzz::kPartSeparator) the PNG (grid.png).
#include "evaluator/formats/map/map_file.h"
#include "evaluator/formats/map/mrpt_gridmap_format.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/seed_data.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  const std::filesystem::path folder = seeds.folder() / "written";
  std::filesystem::create_directories(folder);
  ev::WriteMrptGridmap(fuzz::SeedGrid(), folder / "grid.png");
  seeds.Add("simulated",
            fuzz::JoinParts({fuzz::FileBytes(folder / "grid_limits.txt"), fuzz::FileBytes(folder / "grid.png")}));
  std::filesystem::remove_all(folder);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto parts = fuzz::SplitParts(fuzz::Bytes(data, size), 2);
  const std::filesystem::path limits = fuzz::WriteInput("grid_limits.txt", parts[0]);
  const std::filesystem::path image = fuzz::WriteInput("grid.png", parts[1]);
  fuzz::ExpectReadOrInputError({limits, image}, [&] { ev::ReadMap(image); });
  return 0;
}
