#include "orchestrator/reference_map/reference_map.h"

#include <chrono>
#include <exception>
#include <system_error>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/map_file.h"
#include "evaluator/map_compare/map_resample.h"
#include "evaluator/occupancy_mapping/occupancy_mapper.h"
#include "evaluator/catalog/catalog.h"
#include "orchestrator/adapters/rendered_map.h"
#include "orchestrator/adapters/run_inputs.h"
#include "orchestrator/matrix/run_id.h"
#include "orchestrator/reference_map/reference_map_cache.h"
#include "orchestrator/run/run_json.h"

namespace slamsweep::orchestrator::inline reference_map {
namespace {

namespace fs = std::filesystem;
namespace ev = slamsweep::evaluator;
using nlohmann::json;

/// The sequence's clean scans and reference poses, cut like the run's, rendered as the odometry
/// baseline renders its map, reduced to the classes map comparison sees (so that the cache's
/// trinary file holds exactly the same cells).
ev::OccupancyGrid Render(const RunSpec& spec) {
  ev::Sequence sequence = ev::LoadCatalogSequence(spec.sequence.entry, {});
  if (spec.sequence.max_scans) sequence = CutSequence(std::move(sequence), *spec.sequence.max_scans);
  if (!sequence.reference) {
    throw ev::InputError("sequence '" + spec.sequence.entry.name +
                         "' has no reference trajectory to render a map from");
  }
  EvaluationOptions evaluation = spec.evaluation;
  evaluation.stages = 0;
  return ev::ClassifyCells(RenderMapFromTrajectory(sequence.scans, *sequence.reference, evaluation).grid);
}

}  // namespace

json ReferenceMap::ToJson() const {
  json out = {
      {"source", source}, {"file", file.string()}, {"resolution_m", grid.resolution_m}, {"from_cache", from_cache}};
  if (!cache_problem.empty()) out["cache_problem"] = cache_problem;
  return out;
}

fs::path ReferenceMapCacheDir(const fs::path& run_dir) {
  fs::path dir = run_dir.lexically_normal();
  if (dir.filename().empty()) dir = dir.parent_path();  // "runs/r1/" -> "runs/r1"
  return dir.parent_path().parent_path() / "reference_maps";
}

json ReferenceMapKey(const RunSpec& spec) {
  json sequence = ToJson(spec.sequence.entry);
  // What is said about the data, not the data.
  for (const char* words : {"citation", "licence", "download"}) sequence.erase(words);
  json key = {{"sequence", std::move(sequence)},
              {"max_scans", spec.sequence.max_scans ? json(*spec.sequence.max_scans) : json()},
              {"resolution_m", spec.evaluation.map_resolution_m},
              {"mapper", RenderMapperOptions(spec.evaluation)},
              {"mapper_revision", ev::kOccupancyMapperRevision}};
  if (!spec.sequence.entry.path.empty()) {
    // The same path may hold another file later (a re-downloaded dataset): its size and time say so.
    std::error_code error;
    const auto size = fs::file_size(spec.sequence.entry.path, error);
    const auto modified = fs::last_write_time(spec.sequence.entry.path, error);
    if (!error) {
      key["file"] = {
          {"size", size},
          {"modified_ns", std::chrono::duration_cast<std::chrono::nanoseconds>(modified.time_since_epoch()).count()}};
    }
  }
  return key;
}

std::string ReferenceMapCacheName(const RunSpec& spec) {
  return fmt::format("{}-{:016x}", SanitizeIdPart(spec.sequence.entry.name), Fnv1a64(ReferenceMapKey(spec).dump()));
}

std::optional<ReferenceMap> LoadReferenceMap(const RunSpec& spec, bool sequence_has_reference,
                                             const fs::path& cache_dir) {
  const double resolution_m = spec.evaluation.map_resolution_m;
  if (!spec.sequence.entry.reference_map_path.empty()) {
    ReferenceMap map;
    map.source = "file";
    map.file = spec.sequence.entry.reference_map_path;
    map.grid = ev::ResampleToResolution(ev::ReadMap(map.file), resolution_m);
    return map;
  }
  if (!sequence_has_reference) return std::nullopt;

  ReferenceMap map;
  map.source = "rendered";
  // A rendering problem is the run's (an unreadable sequence); a cache problem (a read-only or
  // full disk) is not: the map is then rendered for this run alone.
  struct RenderFailure {
    std::string message;
  };
  const auto render = [&] {
    try {
      return Render(spec);
    } catch (const ev::InputError& error) {
      throw RenderFailure{error.what()};
    }
  };
  try {
    MapCache::Entry entry =
        MapCache(cache_dir).LoadOrRender(ReferenceMapCacheName(spec), ReferenceMapKey(spec), render);
    map.grid = std::move(entry.grid);
    map.file = entry.yaml;
    map.from_cache = entry.found;
  } catch (const RenderFailure& failure) {
    throw ev::InputError(failure.message);
  } catch (const std::exception& error) {
    map.cache_problem = error.what();
    map.grid = Render(spec);
  }
  return map;
}

}  // namespace slamsweep::orchestrator::inline reference_map
