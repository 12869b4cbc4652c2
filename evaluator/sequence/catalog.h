#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/sequence/sequence_file.h"

namespace YAML {
class Node;
}  // namespace YAML

namespace slamsweep::evaluator {

/// How a catalog sequence can be scored.
enum class GroundTruthKind {
  kCorrectedPoses,  ///< a SLAM-corrected trajectory logged with the scans ("corrected" CARMEN logs)
  kExact,           ///< the true poses (simulated sequences)
  kRelationsOnly,   ///< Kuemmerle et al. relations and nothing else
  kNone,
};

/// "corrected_poses", "exact", "relations_only", "none".
std::string_view GroundTruthKindName(GroundTruthKind kind);

/// One named sequence of configs/datasets.yaml. Paths may hold ${VARIABLE}s (see ResolveCatalogPath).
struct CatalogEntry {
  std::string name;
  /// "carmen", "rawlog", "rosbag" or "simulated".
  std::string format;
  /// The file (empty for simulated sequences).
  std::string path;
  GroundTruthKind ground_truth = GroundTruthKind::kNone;
  /// Kuemmerle et al. relations, and the offset that brings their stamps onto the log's clock.
  std::string relations_path;
  double relations_offset_s = 0.0;
  /// Overrides the CARMEN max range where the log's own value (or CARMEN's 80 m) is wrong.
  std::optional<double> max_range_m;
  /// "auto", "recorded" or "record_order" (see StampPolicy).
  std::string stamp_policy = "auto";
  std::string citation;
  std::string licence_note;
  /// Where to get the file when it is not there (shown in the "missing file" error).
  std::string download_hint;
  /// Simulated sequences: SimulationOptions as JSON (validated when the catalog is read).
  nlohmann::json simulation;
  /// A reference map file (map_server YAML + image) to score maps against instead of the map
  /// rendered from the reference poses; empty: rendered (orchestrator/reference_map). Truth:
  /// only the worker reads it, after the program has exited.
  std::string reference_map_path;
  /// Line of the entry in the catalog file (from 1), for messages.
  std::size_t line = 0;
};

struct Catalog {
  std::filesystem::path source;
  std::vector<CatalogEntry> entries;
};

/// Values for ${NAME} in catalog paths, e.g. {"SHARED", "/work/shared"}.
using CatalogVariables = std::map<std::string, std::string, std::less<>>;

/// Parses the YAML text of a catalog: a top-level map with `sequences` (and `x-...` keys, ignored, that
/// hold YAML anchors shared by entries), a list of maps with the
/// fields of CatalogEntry (name, format, path, ground_truth, relations, relations_offset_s,
/// max_range_m, stamp_policy, citation, licence, download, simulation, reference_map). An unknown key, a missing
/// name/format/ground_truth, a duplicate name or a value of the wrong kind is an InputError
/// "FILE:LINE: ..." at the offending node.
Catalog ParseCatalog(std::string_view yaml_text, const std::filesystem::path& source);
Catalog ReadCatalog(const std::filesystem::path& path);

/// One entry of the `sequences` list, checked exactly as ParseCatalog checks it (errors
/// "FILE:LINE: ..." with `source` as FILE); for sequences written inline in other YAML files
/// (sweep configs). Include <yaml-cpp/yaml.h> to call it.
CatalogEntry ParseCatalogEntry(const std::filesystem::path& source, const YAML::Node& node);

/// The entry named `name`; InputError listing the known names otherwise.
const CatalogEntry& FindCatalogEntry(const Catalog& catalog, std::string_view name);

/// `path` with every ${NAME} replaced by its value; an unknown variable is an InputError naming it.
std::filesystem::path ResolveCatalogPath(std::string_view path, const CatalogVariables& variables);

/// The sequence of a catalog entry: the file read with the entry's options, or the simulated
/// sequence generated from its options. A missing file is an InputError naming the entry, the path and
/// the download hint.
Sequence LoadCatalogSequence(const CatalogEntry& entry, const CatalogVariables& variables);

}  // namespace slamsweep::evaluator
