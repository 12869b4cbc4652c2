// Orchestration cost of a sweep, measured end to end through the real supervising loop, process
// set and results store: workers are tiny shell scripts, so everything beyond their own time is
// slamsweep's overhead. Also the makespan of equal runs against the ideal total / jobs.
#include <benchmark/benchmark.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "orchestrator/sweep/local_executor.h"
#include "orchestrator/sweep/sweep_runner.h"

namespace slamsweep::orchestrator {
namespace {

std::filesystem::path MakeScratch(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("slamsweep_bench_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// A stand-in for `slamsweep worker RUN_DIR` that sleeps `sleep_s` and writes an ok result.
std::filesystem::path FakeWorker(const std::filesystem::path& dir, double sleep_s) {
  const auto file = dir / "fake_worker.sh";
  std::ofstream out(file);
  out << "#!/bin/sh\n";
  if (sleep_s > 0) out << "sleep " << sleep_s << "\n";
  out << "printf '{\"run_id\":\"%s\",\"status\":\"ok\",\"wall_s\":" << sleep_s
      << ",\"metrics\":[]}' \"${2##*/}\" > \"$2/result.json\"\n";
  out.close();
  std::filesystem::permissions(file, std::filesystem::perms::owner_all);
  return file;
}

std::vector<RunSpec> Runs(std::size_t count) {
  std::vector<RunSpec> runs(count);
  for (std::size_t i = 0; i < count; ++i) {
    runs[i].run_id = "bench-run-" + std::to_string(i);
    runs[i].algorithm.name = "bench";
    runs[i].algorithm.adapter = "command";
    runs[i].sequence.entry.name = "seq";
    runs[i].iteration = static_cast<int>(i);
  }
  return runs;
}

class QuietStatus final : public Status {
 public:
  void Planned(std::size_t, std::size_t) override {}
  void Started(const std::string&) override {}
  void Finished(const FinishedRun&) override {}
  void Message(const std::string&) override {}
  void Done() override {}
};

double SweepSeconds(std::size_t count, std::size_t jobs, double sleep_s) {
  const auto dir = MakeScratch("sweep");
  LocalExecutor executor(FakeWorker(dir, sleep_s));
  QuietStatus status;
  SweepSettings settings;
  settings.name = "bench";
  settings.output_dir = dir / "out";
  settings.jobs = jobs;
  const auto start = std::chrono::steady_clock::now();
  const SweepOutcome outcome = RunSweep(Runs(count), settings, executor, status);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::filesystem::remove_all(dir);
  if (outcome.ok != count) throw std::runtime_error("bench sweep had failed runs");
  return seconds;
}

/// Per-run overhead: 1,000 runs of a program that does nothing, on 2 slots; the figure is wall time
/// per run (the workers' own time, a shell start-up, is included, so this is an upper bound).
void BM_SweepOverheadPerRun(benchmark::State& state) {
  const std::size_t count = static_cast<std::size_t>(state.range(0));
  for (auto _ : state) {
    const double seconds = SweepSeconds(count, 2, 0.0);
    state.SetIterationTime(seconds);
    state.counters["ms_per_run"] = 1000.0 * seconds / static_cast<double>(count);
  }
}
BENCHMARK(BM_SweepOverheadPerRun)->Arg(1000)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);

/// Makespan of `count` equal runs of 0.5 s on `jobs` slots against the ideal count * 0.5 / jobs.
void BM_Makespan(benchmark::State& state) {
  const std::size_t count = static_cast<std::size_t>(state.range(0));
  const std::size_t jobs = static_cast<std::size_t>(state.range(1));
  constexpr double kRunS = 0.5;
  for (auto _ : state) {
    const double seconds = SweepSeconds(count, jobs, kRunS);
    state.SetIterationTime(seconds);
    const double ideal = kRunS * static_cast<double>((count + jobs - 1) / jobs);
    state.counters["ideal_s"] = ideal;
    state.counters["over_ideal_pct"] = 100.0 * (seconds - ideal) / ideal;
  }
}
BENCHMARK(BM_Makespan)->Args({40, 4})->Args({40, 8})->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace slamsweep::orchestrator

BENCHMARK_MAIN();
