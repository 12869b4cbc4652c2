#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "evaluator/sequence/odometry_mode.h"
#include "evaluator/sequence_io/sequence_file.h"

namespace YAML {
class Node;
}  // namespace YAML

namespace slamsweep::evaluator::inline catalog {

/// How a catalog sequence can be scored.
enum class GroundTruthKind {
  kCorrectedPoses,  ///< a SLAM-corrected trajectory logged with the scans ("corrected" CARMEN logs)
  kExact,           ///< the true poses (simulated sequences)
  kRelationsOnly,   ///< Kuemmerle et al. relations and nothing else
  kNone,
};

/// "corrected_poses", "exact", "relations_only", "none".
std::string_view GroundTruthKindName(GroundTruthKind kind);
/// Inverse of GroundTruthKindName; InputError naming `option` and the accepted names otherwise.
GroundTruthKind ParseGroundTruthKind(std::string_view text, std::string_view option = "ground_truth");

/// The corrected CARMEN log of the same run as a subsampled log (MRPT's every-5th-scan intel rawlog):
/// its recorded ODOM readings, one per raw scan, give the subsampled log's scan first_scan + j the
/// time of reading first_reading + every * j (both counted from 0 in file order; scans before
/// first_scan are not in the corrected log's run and are dropped); its corrected poses are the
/// reference, and the relations are mapped onto the run's raw scans through it.
struct CorrectedLogLink {
  std::string path;
  std::size_t first_scan = 0;
  std::size_t first_reading = 0;
  std::size_t every = 1;
  bool operator==(const CorrectedLogLink&) const = default;
};

/// One named sequence of configs/datasets.yaml. Paths may hold ${VARIABLE}s (see ResolveCatalogPath).
struct CatalogEntry {
  std::string name;
  /// "carmen", "rawlog", "rosbag" or "simulated".
  std::string format;
  /// The file (empty for simulated sequences).
  std::string path;
  GroundTruthKind ground_truth = GroundTruthKind::kNone;
  /// Kuemmerle et al. relations, and the clock map that brings their stamps onto the log's clock:
  /// t_log = relations_rate * t_relations + relations_offset_s.
  std::string relations_path;
  double relations_offset_s = 0.0;
  double relations_rate = 1.0;
  /// [from, to] in seconds on the relations file's own clock: the sequence is the part of the log between
  /// them (scans by the clock map above), scored on the relations with both stamps inside. Several logs of
  /// one run (keyframes, every 5th scan, every scan) cut to one window are scored on the same relations.
  std::optional<std::array<double, 2>> relations_window_s;
  /// Which odometry a program gets from a corrected CARMEN log (OdometryMode); unset: the catalog's
  /// default, recorded where the log has an ODOM stream (EffectiveOdometryMode). Set explicitly,
  /// "recorded" on a log without such a stream is an error.
  std::optional<OdometryMode> odometry;
  /// Rawlogs that subsample a run whose corrected log is at hand (see CorrectedLogLink).
  std::optional<CorrectedLogLink> corrected_log;
  /// How the entry's clock maps, time fits and checks were established; shown by `data info`.
  std::string notes;
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

/// Whether a program's odometry on this entry can be the reference: a CARMEN log whose logged poses
/// are the corrected poses (ground_truth corrected_poses). Only there does the odometry mode matter.
bool OdometryModeApplies(const CatalogEntry& entry);

/// Whether a CARMEN log's logged pose (FLASER x y theta, ROBOTLASER1 robot pose) is its reference: only
/// under ground_truth corrected_poses (the Radish/Freiburg logs, GMapping's output) or exact. Under
/// relations_only or none the log is raw: the logged pose is the robot's odometry and there is no
/// reference trajectory.
bool LoggedPoseIsReference(const CatalogEntry& entry);

/// The odometry mode runs on `entry` use: its `odometry`, else "recorded". Entries where the mode
/// does not apply (OdometryModeApplies) have only their recorded odometry: "recorded".
OdometryMode EffectiveOdometryMode(const CatalogEntry& entry);

/// Values for ${NAME} in catalog paths, e.g. {"SHARED", "/work/shared"}.
using CatalogVariables = std::map<std::string, std::string, std::less<>>;

/// Parses the YAML text of a catalog: a top-level map with `sequences` (and `x-...` keys, ignored, that
/// hold YAML anchors shared by entries), a list of maps with the
/// fields of CatalogEntry (name, format, path, ground_truth, relations, relations_offset_s,
/// max_range_m, stamp_policy, citation, licence, download, simulation, reference_map, relations_rate,
/// relations_window, odometry, corrected_log, notes). An unknown key, a missing
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

/// The sequence of a catalog entry: the file read with the entry's options (the effective odometry
/// mode; a corrected_log's clock, reference and relations), or the simulated sequence generated from
/// its options. A missing file is an InputError naming the entry, the path and the download hint.
Sequence LoadCatalogSequence(const CatalogEntry& entry, const CatalogVariables& variables);

}  // namespace slamsweep::evaluator::inline catalog
