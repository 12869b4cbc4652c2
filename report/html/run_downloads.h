#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "report/html/site_data.h"
#include "orchestrator/run/run_record.h"

namespace slamsweep::report::inline html {

// What the report takes from a run folder (orchestrator/DESIGN.md) into the run's page and folder.

/// The final map's image: map.png, else map.pgm (the format of earlier run folders).
std::filesystem::path MapImage(const RunRecord& run);

/// The run's stage images: those its result.json names (kept inside the run folder), else, when it names
/// none, the PNGs of its stages/ folder in name order.
std::vector<std::filesystem::path> StagePaths(const RunRecord& run);

/// Links (else copies) the run folder's downloadable files (fixed names, in display order) into `run_out`,
/// and its stage animation, which the page shows as it is; notes in `artifacts` what could not be copied.
void CopyDownloads(const RunRecord& run, const std::filesystem::path& run_out, RunArtifacts& artifacts);

/// Adds `name` (one of the downloadable files) to the run's downloads at its place in the display order.
void AddDownload(RunArtifacts& artifacts, const std::string& name);

/// The end of a run's log.txt.
struct LogTail {
  std::string text;
  bool truncated = false;
};

/// The last `max_lines` lines of `log`, from at most its last 64 KiB; truncated when something was left
/// out. Empty for a missing file.
LogTail ReadLogTail(const std::filesystem::path& log, std::size_t max_lines);

}  // namespace slamsweep::report::inline html
