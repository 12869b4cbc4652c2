// KITTI trajectories (12 numbers of a 3x4 pose matrix per line) with their times file: the input is the
// poses, then (after fuzz::kPartSeparator) the times; without a second part no times file is read.
#include "tests/fuzz/seed_data.h"
#include "tests/fuzz/trajectory_check.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  ev::TrajectoryWriteOptions options;
  options.kitti_times_path = seeds.folder() / "times.txt";
  const std::string poses =
      fuzz::WrittenTrajectory(seeds, fuzz::SeedGroundTruth(30), "written.kitti", ev::TrajectoryFormat::kKitti, options);
  const std::string times = fuzz::FileBytes(options.kitti_times_path);
  std::filesystem::remove(options.kitti_times_path);
  seeds.Add("simulated-with-times.kitti", fuzz::JoinParts({poses, times}));
  seeds.Add("simulated.kitti", poses);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto parts = fuzz::SplitParts(fuzz::Bytes(data, size), 2);
  const std::filesystem::path file = fuzz::WriteInput("input.kitti", parts[0]);
  ev::TrajectoryReadOptions options;
  if (fuzz::Bytes(data, size).find(fuzz::kPartSeparator) != std::string_view::npos) {
    options.kitti_times_path = fuzz::WriteInput("times.txt", parts[1]);
  }
  fuzz::CheckTrajectoryRead({file, "times.txt"}, file, ev::TrajectoryFormat::kKitti, options);
  return 0;
}
