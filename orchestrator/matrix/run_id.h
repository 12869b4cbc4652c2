#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "orchestrator/run/run_spec.h"
#include "orchestrator/run/stable_hash.h"

namespace slamsweep::orchestrator::inline matrix {

/// A readable part of a run id: every character outside [A-Za-z0-9_.-] becomes '_', leading dots
/// are dropped (no hidden folders, no "..") and at most 32 characters are kept; "_" when nothing is left.
std::string SanitizeIdPart(std::string_view text);

/// `<algorithm>-<sequence>-<noise>-i<iteration>-<hash8>` (orchestrator/DESIGN.md "Run ids"): hash8 is
/// the first 8 hex digits of Fnv1a64(RunIdentity(spec).dump()). Safe as one folder name: never holds
/// '/', never starts with '.'. Two runs whose names sanitise alike still differ in hash8.
std::string MakeRunId(const RunSpec& spec);

}  // namespace slamsweep::orchestrator::inline matrix
