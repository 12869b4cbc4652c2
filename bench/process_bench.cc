// Cost of supervising child processes (orchestrator/process): what a run pays before the SLAM program
// does any work. Both measure /bin/true, so the figure is spawn + wait + reap overhead only.
#include <benchmark/benchmark.h>

#include <cstddef>

#include "orchestrator/process/process_set.h"

namespace slamsweep::orchestrator {
namespace {

ProcessSpec TrueSpec() {
  ProcessSpec spec;
  spec.argv = {"/bin/true"};
  return spec;
}

/// One child to completion, as the worker runs a SLAM program. Reported per run (ms).
void RunProcessTrue(benchmark::State& state) {
  const ProcessSpec spec = TrueSpec();
  for (auto _ : state) {
    const ProcessOutcome outcome = RunProcess(spec);
    if (!outcome.ok()) state.SkipWithError(outcome.reason.c_str());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(RunProcessTrue)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The sweep's loop: `slots` children at a time over `runs` children, starting one as each ends.
void ProcessSetTrue(benchmark::State& state) {
  const std::size_t slots = static_cast<std::size_t>(state.range(0));
  const std::size_t runs = static_cast<std::size_t>(state.range(1));
  const ProcessSpec spec = TrueSpec();
  for (auto _ : state) {
    ProcessSet set;
    std::size_t started = 0;
    std::size_t failed = 0;
    while (started < runs || set.running() > 0) {
      while (started < runs && set.running() < slots) {
        set.Start(spec);
        ++started;
      }
      for (const auto& [id, outcome] : set.WaitForAny()) failed += outcome.ok() ? 0 : 1;
    }
    if (failed > 0) state.SkipWithError("some /bin/true runs failed");
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(runs));
  // Wall seconds per child (printed with an SI prefix: "1.4m" = 1.4 ms).
  state.counters["s_per_run"] = benchmark::Counter(
      static_cast<double>(runs), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(ProcessSetTrue)->Args({2, 200})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace slamsweep::orchestrator

BENCHMARK_MAIN();
