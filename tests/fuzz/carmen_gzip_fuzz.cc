// gzip-compressed CARMEN logs (.log.gz, as the shared datasets are): the inflaters (libdeflate, then zlib's
// streaming inflate for damaged data), the cap on inflated size, and the parser behind them.
#include <numbers>
#include <string>

#include "evaluator/sequence_io/robot_log_file.h"
#include "evaluator/sequence_io/sequence_file.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/seed_data.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  const std::string log = ev::FormatCarmenLog(fuzz::SeedLog(12, 181, std::numbers::pi));
  seeds.Add("simulated.log.gz", fuzz::Gzip(log));
  // Two members, as `cat a.gz b.gz` makes them.
  seeds.Add("two-members.log.gz", fuzz::Gzip(log.substr(0, log.size() / 2)) + fuzz::Gzip(log.substr(log.size() / 2)));
  // Past the cap: 17 MiB of comment lines in a few kilobytes.
  seeds.Add("past-the-cap.log.gz", fuzz::Gzip(std::string(17u << 20, '#').replace(0, 1, "\n")));
  for (const char* shared : {"datasets/intel/intel-corrected.log.gz", "datasets/fr101/freiburg-101-corrected.log.gz"}) {
    // The first kilobytes of the compressed file: a gzip stream that ends early.
    if (const auto head = seeds.SharedHead(shared, 6 << 10, /*inflate=*/false, /*whole_lines=*/false)) {
      seeds.Add(std::filesystem::path(shared).filename().string() + ".head", *head);
    }
    if (const auto lines = seeds.SharedHead(shared, 12 << 10)) {
      seeds.Add(std::filesystem::path(shared).filename().string(), fuzz::Gzip(*lines));
    }
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = fuzz::WriteInput("input.log.gz", fuzz::Bytes(data, size));
  fuzz::CheckSequenceRead(file, [&] { return ev::ReadSequence(file); });
  return 0;
}
