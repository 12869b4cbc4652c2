#include "orchestrator/history/series_odometry.h"

#include <set>

#include "evaluator/sequence/catalog.h"
#include "evaluator/sequence/odometry_mode.h"
#include "orchestrator/matrix/run_spec.h"
#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator {
namespace {

using nlohmann::json;

const json* StringAt(const json& object, const char* outer, const char* inner) {
  if (!object.is_object()) return nullptr;
  const auto found = object.find(outer);
  if (found == object.end() || !found->is_object()) return nullptr;
  const auto value = found->find(inner);
  return value != found->end() && value->is_string() ? &*value : nullptr;
}

}  // namespace

bool IsComparableOdometryMode(std::string_view mode) {
  return mode == evaluator::OdometryModeName(evaluator::OdometryMode::kRecorded) ||
         mode == evaluator::OdometryModeName(evaluator::OdometryMode::kReference);
}

std::string OdometryModeOfRunJson(const json& run_json) {
  if (const json* planned = StringAt(run_json, "group", "odometry")) return planned->get<std::string>();
  const json* format = StringAt(run_json, "sequence", "format");
  const json* ground_truth = StringAt(run_json, "sequence", "ground_truth");
  if (format == nullptr || ground_truth == nullptr) return std::string(kOdometryUnknown);
  const bool mode_applies =
      *format == "carmen" &&
      *ground_truth == evaluator::GroundTruthKindName(evaluator::GroundTruthKind::kCorrectedPoses);
  if (!mode_applies) return std::string(evaluator::OdometryModeName(evaluator::OdometryMode::kRecorded));
  // A corrected log: a mode written into the sequence counts; without one the run predates the mode, when
  // programs were given the logged (corrected) pose.
  if (const json* written = StringAt(run_json, "sequence", "odometry")) return written->get<std::string>();
  return std::string(evaluator::OdometryModeName(evaluator::OdometryMode::kReference));
}

std::map<NightCell, std::string> OdometryModesOfResultDir(const std::filesystem::path& result_dir,
                                                         std::int64_t last_sweep_id) {
  std::map<NightCell, std::set<std::string>> seen;
  try {
    const std::filesystem::path database = result_dir / "results.sqlite";
    if (!std::filesystem::exists(database)) return {};
    const ResultsStore store = ResultsStore::OpenExisting(database);
    for (const StoredRun& run : store.Runs()) {
      // Runs a later sweep added to the directory were not part of the night.
      if (run.sweep_id > last_sweep_id) continue;
      seen[{AlgorithmLabel(run.algorithm, run.parameters), run.sequence, run.noise}].insert(
          OdometryModeOfRunJson(run.spec));
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

}  // namespace slamsweep::orchestrator
