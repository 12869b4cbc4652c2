// CARMEN logs (plain text) read as a sweep reads a sequence (ReadSequence): as a corrected log (the logged
// pose is the reference) and with the robot's recorded odometry rebuilt from its ODOM records.
#include <numbers>

#include "evaluator/sequence_io/robot_log_file.h"
#include "evaluator/sequence_io/sequence_file.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/seed_data.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  seeds.Add("simulated-flaser.log", ev::FormatCarmenLog(fuzz::SeedLog(12, 181, std::numbers::pi)));
  seeds.Add("simulated-robotlaser1.log", ev::FormatCarmenLog(fuzz::SeedLog(12, 90, 1.5 * std::numbers::pi)));
  for (const char* log : {"datasets/intel/intel-corrected.log.gz", "datasets/fr079/freiburg-079-corrected.log.gz",
                          "datasets/intel/intel-raw-scans-0-5504.clf.gz", "datasets/orebro/orebro-corrected.log.gz"}) {
    if (const auto head = seeds.SharedHead(log, 24 << 10)) {
      seeds.Add(std::filesystem::path(log).stem().string(), *head);
    }
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = fuzz::WriteInput("input.log", fuzz::Bytes(data, size));
  fuzz::CheckSequenceRead(file, [&] { return ev::ReadSequence(file); });
  ev::SequenceReadOptions recorded;
  recorded.carmen.odometry = ev::OdometryMode::kRecorded;
  recorded.carmen.require_recorded_odometry = false;
  fuzz::CheckSequenceRead(file, [&] { return ev::ReadSequence(file, recorded); });
  return 0;
}
