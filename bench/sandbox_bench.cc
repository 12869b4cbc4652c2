// What the sandbox adds to every run (orchestrator/sandbox): RunProcess of /bin/true plain and in a
// sandbox built as the worker builds it (the system folders, the program's file, input/ read-only,
// raw/ writable, limits, no network). The difference is the sandbox's start-up cost per run (goal:
// under 10 ms), with a /proc of its own and without (as in a container whose /proc Docker masks). "cpu_ms" is the user
// + system time of the child and everything it waited for (bubblewrap, the sandbox's process 1, /bin/true), which a
// loaded machine does not inflate.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "orchestrator/process/process_set.h"
#include "orchestrator/sandbox/sandbox_availability.h"

namespace slamsweep::orchestrator {
namespace {

namespace fs = std::filesystem;

/// A run folder with input/ and raw/, removed at exit.
struct RunFolder {
  RunFolder() {
    root = fs::temp_directory_path() / ("slamsweep-sandbox-bench-" + std::to_string(::getpid()));
    fs::create_directories(root / "input");
    fs::create_directories(root / "raw");
    fs::permissions(root / "raw", fs::perms::all);
  }
  ~RunFolder() {
    std::error_code ignored;
    fs::remove_all(root, ignored);
  }
  fs::path root;
};

void Run(benchmark::State& state, bool sandboxed, bool fresh_proc = true) {
  static const RunFolder folder;
  ProcessSpec spec;
  spec.argv = {"/bin/true"};
  spec.working_dir = folder.root / "raw";
  if (sandboxed) {
    const SandboxPrograms& programs = FindSandboxPrograms();
    if (!programs.missing.empty()) {
      state.SkipWithError(programs.missing.c_str());
      return;
    }
    SandboxSpec sandbox;
    sandbox.bwrap_program = programs.bwrap;
    sandbox.init_program = programs.init;
    sandbox.read_only = {folder.root / "input", "/usr/bin/true"};
    sandbox.writable = {folder.root / "raw"};
    sandbox.process_limit = 1024;
    sandbox.file_size_limit_bytes = std::uint64_t{4096} << 20;
    if (::geteuid() == 0) sandbox.user = SandboxSpec::User{65534, 65534};
    sandbox.fresh_proc = fresh_proc;
    spec.sandbox = sandbox;
  }
  double cpu_s = 0;
  for (auto _ : state) {
    const ProcessOutcome outcome = RunProcess(spec);
    if (!outcome.ok()) {
      state.SkipWithError(outcome.reason.c_str());
      return;
    }
    cpu_s += outcome.cpu_s;
  }
  state.counters["cpu_ms"] = benchmark::Counter(cpu_s * 1e3 / static_cast<double>(state.iterations()));
}

void PlainTrue(benchmark::State& state) { Run(state, false); }
void SandboxedTrue(benchmark::State& state) { Run(state, true); }
void SandboxedTrueWithoutProc(benchmark::State& state) { Run(state, true, false); }
BENCHMARK(PlainTrue)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(SandboxedTrue)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(SandboxedTrueWithoutProc)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

}  // namespace
}  // namespace slamsweep::orchestrator

BENCHMARK_MAIN();
