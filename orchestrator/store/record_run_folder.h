#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator::inline store {

/// Records the run whose folder is `out_dir / run_dir_relative` from its run.json and result.json, the way the
/// sweep does after a worker exits. Throws InputError naming the file when either is missing or malformed.
void RecordRunFolder(ResultsStore& store, std::int64_t sweep_id, const std::filesystem::path& out_dir,
                     const std::string& run_dir_relative);

}  // namespace slamsweep::orchestrator::inline store
