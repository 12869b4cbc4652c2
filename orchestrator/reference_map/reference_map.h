#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "evaluator/core/occupancy_grid.h"
#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline reference_map {

/// A run's reference map: what its map is scored against (evaluator/map_compare). It is truth,
/// exactly like the reference trajectory: only the worker reads or renders it, after the program
/// has exited, and it is never written into the run folder's input/ or raw/.
struct ReferenceMap {
  /// At the evaluation's cell size (evaluation.map_resolution_m).
  evaluator::OccupancyGrid grid;
  /// "rendered" (from the reference poses and the clean scans) or "file" (the catalog's reference_map).
  std::string source;
  /// The map file read: the cache entry (a map_server YAML) or the catalog's file.
  std::filesystem::path file;
  /// Rendered: whether this call found it in the cache (false: this call rendered it).
  bool from_cache = false;
  /// Set when the map could not be cached (it was then rendered for this run alone).
  std::string cache_problem;

  /// {"source", "file", "resolution_m", "from_cache"} for result.json's metric details.
  nlohmann::json ToJson() const;
};

/// The folder that caches the rendered reference maps of a sweep: OUT/reference_maps beside
/// OUT/runs (orchestrator/DESIGN.md), from the run folder OUT/runs/<run-id>.
std::filesystem::path ReferenceMapCacheDir(const std::filesystem::path& run_dir);

/// What a rendered reference map depends on, as canonical JSON: the sequence entry (format, file,
/// its size and modification time, ground truth, reading options, simulation; not its citation),
/// max_scans, the cell size, the mapper's options and kOccupancyMapperRevision. Runs that differ
/// in anything else (algorithm, noise, seed, iteration) share one map.
nlohmann::json ReferenceMapKey(const RunSpec& spec);

/// The cache entry's file stem: "<sequence>-<16 hex digits of the key's FNV-1a>", safe as a file name.
std::string ReferenceMapCacheName(const RunSpec& spec);

/// The run's reference map, or nullopt when its sequence has neither a reference map file nor a
/// reference trajectory (`sequence_has_reference`, known to the worker from the run's inputs). A catalog entry's
/// reference_map file is read (and resampled to the evaluation's cell size when its own differs). Otherwise the map is
/// rendered as the odometry baseline renders its map (the same occupancy mapping), at the evaluation's cell size, from
/// the sequence's reference poses and its CLEAN scans (before the run's range noise), cut to the
/// run's max_scans, and cached in `cache_dir` under ReferenceMapCacheName: many workers may ask
/// at once; one renders (under an exclusive lock on the entry), the others wait and read it;
/// files are renamed into place complete, and a damaged entry is rendered again. Every caller,
/// the one that rendered included, gets the map as read back from the cache; the map holds only
/// the classes map comparison sees (occupied, free, unknown), which the file keeps exactly. When the cache cannot be
/// written the map is rendered for this run alone and `cache_problem` says why. Throws InputError when the map file or
/// the sequence cannot be read or the map cannot be rendered.
std::optional<ReferenceMap> LoadReferenceMap(const RunSpec& spec, bool sequence_has_reference,
                                             const std::filesystem::path& cache_dir);

}  // namespace slamsweep::orchestrator::inline reference_map
