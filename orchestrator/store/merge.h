#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace slamsweep::orchestrator::inline store {

/// What MergeResultDirs did.
struct MergeReport {
  /// Runs that were not in the output before.
  std::size_t runs_added = 0;
  /// Runs found again with the same result (kept once).
  std::size_t duplicates = 0;
  /// One sentence per run id found with different results; the newer finished_at was kept.
  std::vector<std::string> conflicts;
  /// Other things worth a look (a run recorded in a store whose folder is missing).
  std::vector<std::string> warnings;
};

/// Combines output directories (shards of one sweep run on several machines, or re-runs) into `out`:
/// each input's runs/<id>/ folder is hard-linked (copied across file systems) into out/runs/ when out does
/// not have it, its sweeps, runs and metrics are added to out/results.sqlite, and summary.json and junit.xml
/// are rewritten from the merged store. The same run id with equal result.json is kept once; with different
/// results the one with the later finished_at wins (ties: the earlier input) and a conflict is reported.
/// Throws InputError naming the file when an input has no results.sqlite or a store is unusable, and when an
/// input is `out` itself.
MergeReport MergeResultDirs(const std::vector<std::filesystem::path>& inputs, const std::filesystem::path& out);

}  // namespace slamsweep::orchestrator::inline store
