#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <tuple>

#include "orchestrator/run/run_json.h"

namespace slamsweep::orchestrator::inline history {

// kOdometryUnknown (orchestrator/run/run_json.h) also marks a history series whose night was recorded before
// the history kept the mode and whose results are gone: never compared with anything.

/// The mode of an old series whose night had runs of both modes in one cell: its samples were pooled before
/// the history kept the mode and cannot be told apart. Never compared with anything.
inline constexpr std::string_view kOdometryMixed = "mixed";

/// Whether a series of this mode may be compared with another night's series of the same mode: "recorded" and
/// "reference" only.
bool IsComparableOdometryMode(std::string_view mode);

/// A cell of a night: algorithm label x sequence x noise.
using NightCell = std::tuple<std::string, std::string, std::string>;

/// The odometry mode of each cell of the night recorded from `result_dir` (its results.sqlite) up to sweep
/// `last_sweep_id`: one mode, or kOdometryMixed when the cell's runs had both. Empty when the directory or its
/// database is gone or unreadable (the caller marks that night's series kOdometryUnknown).
std::map<NightCell, std::string> OdometryModesOfResultDir(const std::filesystem::path& result_dir,
                                                          std::int64_t last_sweep_id);

}  // namespace slamsweep::orchestrator::inline history
