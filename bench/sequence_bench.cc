// Speed of reading CARMEN logs into a Sequence (target: fr079, 4791 scans x 360 beams, under 100 ms).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "evaluator/core/text_file.h"
#include "evaluator/formats/trajectory/carmen_log.h"
#include "evaluator/sequence/carmen_sequence.h"

namespace slamsweep::evaluator {
namespace {

std::filesystem::path SharedDataset(const std::string& relative) {
  return std::filesystem::path(SLAMSWEEP_SHARED_DIR) / "datasets" / relative;
}

/// The whole path a user pays for: gzip inflate, parse, build the Sequence.
void ReadSequence(benchmark::State& state, const std::string& relative) {
  const std::filesystem::path path = SharedDataset(relative);
  if (!std::filesystem::exists(path)) {
    state.SkipWithError(("missing " + path.string()).c_str());
    return;
  }
  std::size_t scans = 0;
  for (auto _ : state) {
    const Sequence sequence = ReadCarmenSequence(path);
    scans = sequence.scans.size();
    benchmark::DoNotOptimize(sequence.scans.data());
  }
  state.counters["scans"] = static_cast<double>(scans);
}

/// The stages on their own, to see where the time goes. Inflate is core's ReadTextFile: the whole
/// file inflated by libdeflate, as ReadCarmenLog does before it parses.
void Inflate(benchmark::State& state, const std::string& relative) {
  const std::filesystem::path path = SharedDataset(relative);
  if (!std::filesystem::exists(path)) {
    state.SkipWithError(("missing " + path.string()).c_str());
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(ReadTextFile(path).size());
}

void Parse(benchmark::State& state, const std::string& relative) {
  const std::filesystem::path path = SharedDataset(relative);
  if (!std::filesystem::exists(path)) {
    state.SkipWithError(("missing " + path.string()).c_str());
    return;
  }
  const std::string content = ReadTextFile(path);
  for (auto _ : state) benchmark::DoNotOptimize(ParseCarmenLog(content, path).lasers.size());
}

BENCHMARK_CAPTURE(ReadSequence, fr079, std::string("fr079/freiburg-079-corrected.log.gz"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ReadSequence, intel, std::string("intel/intel-corrected.log.gz"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Inflate, fr079, std::string("fr079/freiburg-079-corrected.log.gz"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Parse, fr079, std::string("fr079/freiburg-079-corrected.log.gz"))->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace slamsweep::evaluator

BENCHMARK_MAIN();
