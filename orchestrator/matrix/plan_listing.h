#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline matrix {

/// ParametersText of a run's parameters ("k=v;k=v", keys sorted, text values unquoted); "-" when there are none.
std::string FormatParameters(const nlohmann::json& parameters);

/// One "warning: ..." line per sequence x noise cell whose runs get the reference as odometry
/// (RunSpec::odometry_is_reference), naming the runs; "" when there are none.
std::string OdometryIsReferenceWarnings(const std::vector<RunSpec>& runs);

/// The text of `slamsweep plan`: a header, one line per run (id, algorithm, parameters, sequence, noise,
/// iteration, seed), then "N runs". Columns are padded so a terminal shows a table.
std::string FormatPlan(const std::vector<RunSpec>& runs);

/// `slamsweep plan --json`: an array of run.json objects (ToJson of each run).
nlohmann::json PlanJson(const std::vector<RunSpec>& runs);

}  // namespace slamsweep::orchestrator::inline matrix
