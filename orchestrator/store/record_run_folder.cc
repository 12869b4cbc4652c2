#include "orchestrator/store/record_run_folder.h"

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/run/run_folder.h"

namespace slamsweep::orchestrator::inline store {

using evaluator::InputError;

void RecordRunFolder(ResultsStore& store, std::int64_t sweep_id, const std::filesystem::path& out_dir,
                     const std::string& run_dir_relative) {
  const std::filesystem::path folder = out_dir / run_dir_relative;
  const nlohmann::json spec = ReadJsonFile(folder / "run.json");
  const nlohmann::json result = ReadJsonFile(folder / "result.json");
  try {
    store.RecordRun(sweep_id, spec, result, run_dir_relative);
  } catch (const InputError& e) {
    // RecordRun names the field; the folder tells which of the many runs it was.
    throw InputError(fmt::format("{}: {}", folder.string(), e.what()));
  }
}

}  // namespace slamsweep::orchestrator::inline store
