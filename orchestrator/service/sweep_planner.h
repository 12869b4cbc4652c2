#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "orchestrator/config/input_policy.h"
#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::service {

/// A submitted sweep file read, validated and expanded, with its runs' build identity stamped: what
/// `slamsweep plan` would list for the same file.
struct PlannedSweep {
  std::string name;
  std::vector<RunSpec> runs;
  /// Digest of the file's text, recorded with the sweep (as `slamsweep run` records its config's).
  std::string config_hash;
  /// The validity study the file names (validity_study:), empty when none: copied into the result directory.
  std::filesystem::path validity_study;
};

/// What a submitted sweep may ask for.
struct PlanLimits {
  InputPolicy policy;
  std::uint64_t max_runs = 0;
};

/// Reads a sweep file's text. `file` names it in messages and anchors its relative paths. Throws
/// InputError ("FILE:LINE:COLUMN: ..."), PolicyError (a path outside the roots, a command adapter
/// not allowed) or MatrixTooLargeError (more than max_runs runs). The command line supplies it (the
/// same loading as `slamsweep plan`), so the service never reads a sweep differently from `run`.
using SweepPlanner = std::function<PlannedSweep(std::string_view yaml_text, const std::filesystem::path& file,
                                                const PlanLimits& limits)>;

/// Writes a finished sweep's HTML report into RESULT_DIR/report (the command line supplies it: the
/// report is not the orchestrator's business). Throws on failure.
using ReportWriter = std::function<void(const std::filesystem::path& result_dir)>;

}  // namespace slamsweep::orchestrator::service
