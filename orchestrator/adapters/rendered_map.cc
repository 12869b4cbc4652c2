#include "orchestrator/adapters/rendered_map.h"

#include "evaluator/occupancy_mapping/occupancy_mapper.h"
#include "evaluator/occupancy_mapping/scan_placement.h"
#include "orchestrator/adapters/stage_image.h"

namespace slamsweep::orchestrator::inline adapters {

namespace ev = slamsweep::evaluator;

ev::OccupancyMapperOptions RenderMapperOptions(const EvaluationOptions& evaluation) {
  ev::OccupancyMapperOptions options;
  options.resolution_m = evaluation.map_resolution_m;
  return options;
}

RenderedMap RenderMapFromTrajectory(std::span<const ev::LaserScan> scans, const ev::Trajectory& trajectory,
                                    const EvaluationOptions& evaluation) {
  const ev::ScanPlacement placement = ev::PlaceScans(scans, trajectory);
  const ev::OccupancyMapper mapper(RenderMapperOptions(evaluation));

  RenderedMap rendered;
  rendered.scans_used = placement.placed.size();
  rendered.scans_outside_trajectory = placement.outside_trajectory;
  if (evaluation.stages == 0) {
    rendered.grid = mapper.Build(placement.placed);
    return rendered;
  }
  // One incremental build gives every stage and, as its last stage, the final map.
  const std::vector<std::size_t> ends = ev::EvenlySpacedStages(placement.placed.size(), evaluation.stages);
  mapper.RenderStages(placement.placed, ends, [&](const ev::MapStage& stage) {
    rendered.stages.push_back(StageImage(stage.grid));
    if (stage.scans_integrated == placement.placed.size()) rendered.grid = stage.grid;
  });
  return rendered;
}

}  // namespace slamsweep::orchestrator::inline adapters
