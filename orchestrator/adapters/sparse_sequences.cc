#include "orchestrator/adapters/sparse_sequences.h"

#include <optional>
#include <set>
#include <utility>

#include "evaluator/core/input_error.h"
#include "evaluator/sequence/scan_spacing.h"
#include "orchestrator/adapters/run_inputs.h"
#include "orchestrator/input_cache/prepared_sequence_cache.h"

namespace slamsweep::orchestrator::inline adapters {

std::string SparseSequenceWarnings(const std::vector<RunSpec>& runs, const std::filesystem::path& cache_dir) {
  // A sequence is its catalog entry with its cut: runs differing only in algorithm, noise or seed share it.
  std::set<std::pair<std::string, std::size_t>> seen;
  std::string text;
  for (const RunSpec& run : runs) {
    if (!seen.emplace(run.sequence.entry.name, run.sequence.max_scans.value_or(0)).second) continue;
    std::optional<evaluator::ScanSpacing> spacing;
    try {
      const auto prepare = [&run] { return LoadRunSequence(run); };
      spacing = evaluator::ComputeScanSpacing(
          cache_dir.empty() ? prepare() : LoadOrPrepareSequence(run, cache_dir, prepare).sequence);
    } catch (const evaluator::InputError&) {
      continue;
    }
    if (!spacing) continue;
    const std::string warning = evaluator::SparseScanWarning(*spacing);
    if (!warning.empty()) text += "warning: sequence '" + run.sequence.entry.name + "': " + warning + "\n";
  }
  return text;
}

}  // namespace slamsweep::orchestrator::inline adapters
