#pragma once

#include <string>

namespace slamsweep::orchestrator::inline store {

/// Now as ISO 8601 UTC with seconds ("2026-11-22T05:00:00Z").
std::string UtcNowIso8601();

}  // namespace slamsweep::orchestrator::inline store
