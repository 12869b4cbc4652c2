#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/core/trajectory.h"
#include "orchestrator/adapters/adapter.h"
#include "orchestrator/adapters/run_paths.h"

namespace slamsweep::orchestrator::inline worker {

/// Writes a run's converted outputs in the run folder's fixed layout: map.png + map.yaml
/// (map_saver trinary, as an 8-bit grey PNG), trajectory.tum, reference.tum (when `reference`),
/// stages.png (every stage map, in build order, as one animated PNG; stages of different sizes centred on
/// a canvas of the largest width and height, unknown around them). No map.geojson: the borders are traced
/// from the map when wanted (the report, `slamsweep vectorize`). Returns result.json's `outputs` object
/// (paths relative to the run folder; log.txt when it exists). With `written_map`, it receives the map as
/// map.yaml reads back (evaluator::WriteMapServerAndReadBack: what the map-versus-reference scores count),
/// without decoding map.png again. A map or trajectory that cannot be written is an InputError.
nlohmann::json WriteRunOutputs(const RunPaths& paths, const CollectedOutputs& collected,
                               const evaluator::Trajectory* reference, evaluator::OccupancyGrid* written_map = nullptr);

}  // namespace slamsweep::orchestrator::inline worker
