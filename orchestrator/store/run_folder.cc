#include "orchestrator/store/run_folder.h"

#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator {

using evaluator::InputError;

nlohmann::json ReadJsonFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot read (missing or not readable)", file.string()));
  const std::string text(std::istreambuf_iterator<char>(in), {});
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(fmt::format("{}: not valid JSON: {}", file.string(), e.what()));
  }
}

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

}  // namespace slamsweep::orchestrator
