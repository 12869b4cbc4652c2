// A CARMEN log read as a trajectory (the laser records' poses and clock), as `eval ape` reads it.
#include <numbers>

#include "evaluator/sequence_io/robot_log_file.h"
#include "tests/fuzz/seed_data.h"
#include "tests/fuzz/trajectory_check.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  seeds.Add("simulated.log",
            fuzz::WrittenTrajectory(seeds, fuzz::SeedGroundTruth(30), "written.log", ev::TrajectoryFormat::kCarmen));
  seeds.Add("simulated-scans.log", ev::FormatCarmenLog(fuzz::SeedLog(8, 181, std::numbers::pi)));
  if (const auto head = seeds.SharedHead("datasets/intel/intel-corrected.log.gz", 16 << 10)) {
    seeds.Add("intel-corrected.log", *head);
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = fuzz::WriteInput("input.log", fuzz::Bytes(data, size));
  fuzz::CheckTrajectoryRead({file}, file, ev::TrajectoryFormat::kCarmen);
  return 0;
}
