// MRPT path files (icp-slam's and rbpf-slam's log_estimated_path.txt).
#include "tests/fuzz/seed_data.h"
#include "tests/fuzz/trajectory_check.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  for (const auto& [name, layout] : {std::pair{"rbpf-slam.txt", ev::MrptPathLayout::kRbpfSlam},
                                     std::pair{"icp-slam.txt", ev::MrptPathLayout::kIcpSlam}}) {
    ev::TrajectoryWriteOptions options;
    options.mrpt_layout = layout;
    seeds.Add(name, fuzz::WrittenTrajectory(seeds, fuzz::SeedGroundTruth(30), "log_estimated_path.txt",
                                            ev::TrajectoryFormat::kMrptPath, options));
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = fuzz::WriteInput("log_estimated_path.txt", fuzz::Bytes(data, size));
  fuzz::CheckTrajectoryRead({file}, file, ev::TrajectoryFormat::kMrptPath);
  return 0;
}
