#include "orchestrator/history/series_odometry.h"

#include <set>

#include "evaluator/sequence/odometry_mode.h"
#include "orchestrator/run/run_json.h"
#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator::inline history {

bool IsComparableOdometryMode(std::string_view mode) {
  return mode == evaluator::OdometryModeName(evaluator::OdometryMode::kRecorded) ||
         mode == evaluator::OdometryModeName(evaluator::OdometryMode::kReference);
}

std::map<NightCell, std::string> OdometryModesOfResultDir(const std::filesystem::path& result_dir,
                                                          std::int64_t last_sweep_id) {
  std::map<NightCell, std::set<std::string>> seen;
  try {
    const std::filesystem::path database = result_dir / "results.sqlite";
    if (!std::filesystem::exists(database)) return {};
    const ResultsStore store = ResultsStore::OpenExisting(database);
    for (const RunRecord& run : store.Runs()) {
      // Runs a later sweep added to the directory were not part of the night.
      if (run.sweep_id > last_sweep_id) continue;
      seen[{AlgorithmLabel(run.algorithm, run.parameters), run.sequence, run.noise}].insert(
          OdometryModeOfRunJson(run.run_spec));
    }
  } catch (const std::exception&) {
    return {};  // gone or unreadable: the night's series cannot say their mode
  }
  std::map<NightCell, std::string> modes;
  for (const auto& [cell, found] : seen) {
    modes[cell] = found.size() == 1 ? *found.begin() : std::string(kOdometryMixed);
  }
  return modes;
}

}  // namespace slamsweep::orchestrator::inline history
