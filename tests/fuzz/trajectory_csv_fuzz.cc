// CSV trajectories (a header naming the columns, then one pose per row).
#include "tests/fuzz/seed_data.h"
#include "tests/fuzz/trajectory_check.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  seeds.Add("simulated.csv",
            fuzz::WrittenTrajectory(seeds, fuzz::SeedGroundTruth(30), "written.csv", ev::TrajectoryFormat::kCsv));
  seeds.Add("columns.csv", "timestamp,x,y,yaw\n0,0,0,0\n0.1,0.05,0,0.01\n0.2,0.1,0.001,0.02\n");
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = fuzz::WriteInput("input.csv", fuzz::Bytes(data, size));
  fuzz::CheckTrajectoryRead({file}, file, ev::TrajectoryFormat::kCsv);
  return 0;
}
