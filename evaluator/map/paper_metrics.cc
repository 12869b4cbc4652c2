#include "evaluator/map/paper_metrics.h"

#include "evaluator/map/scorable_grid.h"

namespace slamsweep::evaluator {

void Validate(const PaperMetricsOptions& options) {
  Validate(options.occupied);
  Validate(options.corners);
  Validate(options.enclosed);
}

PaperMetrics ComputePaperMetrics(const OccupancyGrid& grid, const PaperMetricsOptions& options) {
  Validate(options);
  const ScorableGrid scorable = ScorableGrid::Check(grid);  // one check for the three metrics
  PaperMetrics metrics;
  metrics.options = options;
  metrics.occupied = ComputeOccupiedProportion(scorable, options.occupied);
  metrics.corners = ComputeCornerCount(scorable, options.corners);
  metrics.enclosed = ComputeEnclosedAreas(scorable, options.enclosed);
  return metrics;
}

nlohmann::json PaperMetrics::ToJson() const {
  return nlohmann::json{{"occupied_to_free_unknown", occupied.occupied_to_free_unknown},
                        {"occupied_to_all", occupied.occupied_to_all},
                        {"unknown_to_all", occupied.unknown_to_all},
                        {"corners", corners.corners},
                        {"enclosed_areas", enclosed.enclosed_areas},
                        {"parameters",
                         {{"profile", "paper"},
                          {"occupied", options.occupied},
                          {"corners", options.corners},
                          {"enclosed", options.enclosed}}},
                        {"details", {{"occupied", occupied}, {"corners", corners}, {"enclosed", enclosed}}}};
}

}  // namespace slamsweep::evaluator
