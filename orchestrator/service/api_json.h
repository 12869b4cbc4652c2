#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "orchestrator/service/sweep_views.h"

namespace slamsweep::orchestrator::service {

/// A sweep as GET /api/sweeps/ID returns it: id, name, state, priority, submitter, times, counts by
/// run state, ETA, report state, message and the links to its files.
nlohmann::json SweepJson(const SweepView& view);

/// A run as GET /api/sweeps/ID/runs lists it.
nlohmann::json RunJson(const RunView& run);

/// {"error": message}: the body of every 4xx/5xx answer.
nlohmann::json ErrorJson(const std::string& message);

}  // namespace slamsweep::orchestrator::service
