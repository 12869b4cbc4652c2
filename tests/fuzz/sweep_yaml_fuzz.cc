// Sweep files (ParseSweepConfig, strict YAML with FILE:LINE:COLUMN errors) as `slamsweep run` and `plan` read
// them: the repository's dataset catalog, ${SHARED} = ../shared, everything allowed.
#include <string>

#include "evaluator/core/input_error.h"
#include "orchestrator/config/sweep_config.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/support/shared_data.h"

namespace fuzz = slamsweep::fuzz;
namespace orch = slamsweep::orchestrator;

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  for (const char* config :
       {"configs/quickstart.yaml", "configs/paper.yaml", "configs/paper-noise.yaml", "configs/radish.yaml",
        "configs/published.yaml", "configs/validity.yaml", "configs/cartographer-intel-study.yaml",
        "configs/slam-constructor-intel-study.yaml", "configs/examples/command-adapter.yaml",
        "configs/examples/parameter-sweep.yaml", "tests/jobs/nightly_sweep.yaml", "tests/jobs/shard_sweep.yaml"}) {
    seeds.Add(std::filesystem::path(config).filename().string(), seeds.SourceFile(config));
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const orch::SweepConfigContext context{
      .default_catalog = std::filesystem::path(SLAMSWEEP_SOURCE_DIR) / "configs" / "datasets.yaml",
      .variables = {{"SHARED", slamsweep::testing::SharedRoot().string()}},
      .policy = {}};
  const std::string_view text = fuzz::Bytes(data, size);
  const std::filesystem::path file = fuzz::WriteInput("sweep.yaml", text);
  fuzz::ExpectReadOrInputError({file}, [&] { orch::ParseSweepConfig(text, file, context); });
  return 0;
}
