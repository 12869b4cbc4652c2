// The body of POST /api/sweeps: what `slamsweep serve` does with it before anything is queued (its planner,
// cli/serve_command.cc: LoadSweepText under the service's policy: files only under ../shared and the
// scratch folder, no command adapter, no network, at most 5000 runs).
#include <string>

#include "cli/sweep_loading.h"
#include "evaluator/core/input_error.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/support/shared_data.h"

namespace fuzz = slamsweep::fuzz;

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  for (const char* config : {"tests/jobs/service_sweep.yaml", "tests/docker/service_sweep.yaml",
                             "configs/quickstart.yaml", "configs/examples/parameter-sweep.yaml"}) {
    seeds.Add(std::filesystem::path(config).filename().string(), seeds.SourceFile(config));
  }
  seeds.Add("odometry.yaml",
            "name: roundtrip\niterations: 3\nseed: 7\nevaluation: {stages: 4}\n"
            "algorithms:\n  - {name: odometry, adapter: odometry, timeout_s: 60}\n"
            "sequences:\n  - {catalog: simulated-floor, name: floor, max_scans: 60}\n"
            "noise:\n  - name: noisy\n    odometry: {alpha1: 0.01, alpha3: 0.01}\n");
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view body = fuzz::Bytes(data, size);
  // The service names the file as submitted, anchored in its data folder; nothing is written there.
  const std::filesystem::path file = fuzz::WriteInput("sweep.yaml", "");
  slamsweep::cli::SweepLimits limits;
  limits.policy.allowed_roots = {slamsweep::testing::SharedRoot(), file.parent_path()};
  limits.policy.allow_commands = false;
  limits.policy.allow_network = false;
  limits.max_runs = 5000;
  fuzz::ExpectReadOrInputError({file}, [&] { slamsweep::cli::LoadSweepText(body, file.string(), {}, limits); });
  return 0;
}
