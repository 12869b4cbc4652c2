#pragma once

#include <array>
#include <string_view>

namespace slamsweep::orchestrator::inline store {

/// The run metrics that grow as a run gets better: the map-versus-reference scores (fractions of
/// matched walls and intersections over union; orchestrator/worker/run_metrics.cc names them). Every
/// other metric a run reports is an error, a distance or a defect count: lower is better.
inline bool HigherIsBetter(std::string_view metric) {
  constexpr std::array<std::string_view, 5> kHigherIsBetter = {"map_accuracy", "map_completeness", "map_f1",
                                                               "map_iou_free", "map_iou_occupied"};
  for (const std::string_view name : kHigherIsBetter) {
    if (metric == name) return true;
  }
  return false;
}

}  // namespace slamsweep::orchestrator::inline store
