#pragma once

#include <filesystem>

#include "report/model/sweep_model.h"

namespace slamsweep::report::inline model {

/// The study a sweep named (validity_study: in its file), as the sweep copied it into the result
/// directory (orchestrator/store/named_study.h): SweepModelOptions with named_study set, or empty
/// options when the sweep named none. Throws evaluator::InputError naming the file when it is there
/// but unreadable.
SweepModelOptions LoadSweepModelOptions(const std::filesystem::path& result_dir);

}  // namespace slamsweep::report::inline model
