#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "orchestrator/matrix/run_spec.h"

namespace slamsweep::orchestrator {

/// "k=v,k=v" of a run's parameters (keys sorted; text values unquoted); "-" when there are none.
std::string FormatParameters(const nlohmann::json& parameters);

/// The text of `slamsweep plan`: a header, one line per run (id, algorithm, parameters, sequence, noise,
/// iteration, seed), then "N runs". Columns are padded so a terminal shows a table.
std::string FormatPlan(const std::vector<RunSpec>& runs);

/// `slamsweep plan --json`: an array of run.json objects (ToJson of each run).
nlohmann::json PlanJson(const std::vector<RunSpec>& runs);

}  // namespace slamsweep::orchestrator
