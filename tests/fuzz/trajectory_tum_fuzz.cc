// TUM trajectories (timestamp tx ty tz qx qy qz qw).
#include "tests/fuzz/seed_data.h"
#include "tests/fuzz/trajectory_check.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  seeds.Add("simulated.tum",
            fuzz::WrittenTrajectory(seeds, fuzz::SeedGroundTruth(30), "written.tum", ev::TrajectoryFormat::kTum));
  for (const char* shared : {"reference/trajectories/intel_gmapping.tum", "reference/trajectories/synth_est_se3.tum",
                             "reference/trajectories/tum_fr1_xyz_groundtruth.txt"}) {
    if (const auto head = seeds.SharedHead(shared, 4 << 10)) {
      seeds.Add(std::filesystem::path(shared).filename().string(), *head);
    }
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = fuzz::WriteInput("input.tum", fuzz::Bytes(data, size));
  fuzz::CheckTrajectoryRead({file}, file, ev::TrajectoryFormat::kTum);
  return 0;
}
