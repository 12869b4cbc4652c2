#include "evaluator/catalog/catalog.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "evaluator/core/utf8_text.h"
#include "evaluator/formats/trajectory/relations_format.h"
#include "evaluator/sequence/corrected_log_clock.h"
#include "evaluator/sequence/relation_stamps.h"
#include "evaluator/sequence/sequence_cut.h"
#include "evaluator/simulation/simulated_sequence.h"

namespace slamsweep::evaluator::inline catalog {
namespace {

constexpr std::string_view kFormats[] = {"carmen", "rawlog", "rosbag", "rosbag2", "simulated"};

bool IsBagFormat(std::string_view format) { return format == "rosbag" || format == "rosbag2"; }

/// yaml-cpp marks count lines from 0.
std::size_t LineOf(const YAML::Node& node) { return static_cast<std::size_t>(node.Mark().line + 1); }

[[noreturn]] void Fail(const std::filesystem::path& source, const YAML::Node& node, const std::string& message) {
  throw InputError(Located(source, LineOf(node), message));
}

/// A map's key as text: a key that is itself a map or a list (`{a: 1}: 2`) is an error at it.
std::string KeyText(const std::filesystem::path& source, const YAML::Node& key) {
  if (!key.IsScalar()) Fail(source, key, "expected a key of plain text, got a map or a list");
  return key.Scalar();
}

std::string Scalar(const std::filesystem::path& source, const YAML::Node& node, std::string_view key) {
  if (!node.IsScalar()) Fail(source, node, fmt::format("{}: expected a text value", key));
  return node.Scalar();
}

double Number(const std::filesystem::path& source, const YAML::Node& node, std::string_view key) {
  const std::string text = Scalar(source, node, key);
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && std::isfinite(value)) return value;
  } catch (const std::exception&) {
  }
  Fail(source, node, fmt::format("{}: expected a finite number, got '{}'", key, text));
}

/// YAML to JSON for the simulation options, so that their strict JSON readers can check them.
nlohmann::json ToJson(const std::filesystem::path& source, const YAML::Node& node) {
  if (node.IsMap()) {
    nlohmann::json object = nlohmann::json::object();
    for (const auto& item : node) object[KeyText(source, item.first)] = ToJson(source, item.second);
    return object;
  }
  if (node.IsSequence()) {
    nlohmann::json array = nlohmann::json::array();
    for (const auto& item : node) array.push_back(ToJson(source, item));
    return array;
  }
  if (!node.IsScalar()) return nullptr;
  const std::string& text = node.Scalar();
  if (text == "true" || text == "false") return text == "true";
  // Integers stay integers: seeds and counts are read as unsigned / int.
  try {
    std::size_t used = 0;
    const long long integer = std::stoll(text, &used);
    if (used == text.size()) return integer;
  } catch (const std::exception&) {
  }
  try {
    std::size_t used = 0;
    const double number = std::stod(text, &used);
    if (used == text.size()) return number;
  } catch (const std::exception&) {
  }
  return text;
}

std::size_t Count(const std::filesystem::path& source, const YAML::Node& node, std::string_view key,
                  std::size_t minimum) {
  const std::string text = Scalar(source, node, key);
  const bool digits = !text.empty() && text.size() < 10 && text.find_first_not_of("0123456789") == std::string::npos;
  if (!digits || std::stoul(text) < minimum) {
    Fail(source, node, fmt::format("{}: expected a whole number >= {}, got '{}'", key, minimum, text));
  }
  return std::stoul(text);
}

std::array<double, 2> ParseWindow(const std::filesystem::path& source, const YAML::Node& node, std::string_view key) {
  if (!node.IsSequence() || node.size() != 2) {
    Fail(source, node, fmt::format("{}: expected [from, to], two stamps in seconds", key));
  }
  const std::array<double, 2> window{Number(source, node[0], key), Number(source, node[1], key)};
  if (!(window[0] < window[1])) {
    Fail(source, node, fmt::format("{}: expected from < to, got [{}, {}]", key, window[0], window[1]));
  }
  return window;
}

CorrectedLogLink ParseCorrectedLog(const std::filesystem::path& source, const YAML::Node& node) {
  if (!node.IsMap()) Fail(source, node, "corrected_log: expected a map with path, first_reading and every");
  CorrectedLogLink link;
  for (const auto& item : node) {
    const std::string key = KeyText(source, item.first);
    if (key == "path") {
      link.path = Scalar(source, item.second, "corrected_log.path");
    } else if (key == "first_scan") {
      link.first_scan = Count(source, item.second, "corrected_log.first_scan", 0);
    } else if (key == "first_reading") {
      link.first_reading = Count(source, item.second, "corrected_log.first_reading", 0);
    } else if (key == "every") {
      link.every = Count(source, item.second, "corrected_log.every", 1);
    } else {
      Fail(source, item.first,
           fmt::format("corrected_log: unknown key '{}' (expected path, first_scan, first_reading, every)", key));
    }
  }
  if (link.path.empty()) Fail(source, node, "corrected_log: no path");
  return link;
}

/// The BagChoices field a catalog key names; nullptr for other keys.
std::string* BagField(BagChoices& bag, std::string_view key) {
  if (key == "scan_topic") return &bag.scan_topic;
  if (key == "odometry_topic") return &bag.odometry_topic;
  if (key == "odom_frame") return &bag.odom_frame;
  if (key == "base_frame") return &bag.base_frame;
  if (key == "laser_frame") return &bag.laser_frame;
  if (key == "reference_topic") return &bag.reference_topic;
  if (key == "reference_frame") return &bag.reference_frame;
  return nullptr;
}

/// Topics and frames belong to bags; a reference recorded in a bag goes with a kind that has poses.
void CheckBagKeys(const std::filesystem::path& source, const YAML::Node& node, const CatalogEntry& entry,
                  const YAML::Node& ground_truth_node, const YAML::Node& bag_node) {
  if (!IsBagFormat(entry.format)) {
    if (!entry.bag.Empty()) {
      Fail(source, bag_node,
           fmt::format("sequence '{}': topics and frames apply to ROS bags (format rosbag or rosbag2), not to "
                       "format {}",
                       entry.name, entry.format));
    }
    if (entry.ground_truth == GroundTruthKind::kMeasured) {
      Fail(source, ground_truth_node,
           fmt::format("sequence '{}': ground_truth measured is a reference recorded in a ROS bag (format rosbag or "
                       "rosbag2, with reference_topic or reference_frame)",
                       entry.name));
    }
    return;
  }
  try {
    CheckBagChoices(entry.bag);
  } catch (const InputError& error) {
    Fail(source, node, fmt::format("sequence '{}': {}", entry.name, error.what()));
  }
  if (GroundTruthHasPoses(entry.ground_truth) && !entry.bag.HasReference()) {
    Fail(source, ground_truth_node,
         fmt::format("sequence '{}': ground_truth {} needs the reference's source in the bag: reference_topic (e.g. "
                     "/ground_truth) or reference_frame (e.g. map)",
                     entry.name, GroundTruthKindName(entry.ground_truth)));
  }
  if (!GroundTruthHasPoses(entry.ground_truth) && entry.bag.HasReference()) {
    Fail(source, ground_truth_node,
         fmt::format("sequence '{}': reference_topic or reference_frame names a reference, but ground_truth is {}; "
                     "say what the reference is with ground_truth measured (recorded with the data), corrected_poses "
                     "or exact",
                     entry.name, GroundTruthKindName(entry.ground_truth)));
  }
}

CatalogEntry ParseEntry(const std::filesystem::path& source, const YAML::Node& node) {
  if (!node.IsMap()) Fail(source, node, "sequences: expected each entry to be a map with name, format, ...");
  CatalogEntry entry;
  entry.line = LineOf(node);
  bool has_ground_truth = false;
  YAML::Node odometry_node;
  YAML::Node ground_truth_node;
  YAML::Node bag_node;
  for (const auto& item : node) {
    const std::string key = KeyText(source, item.first);
    const YAML::Node& value = item.second;
    if (key == "name") {
      entry.name = Scalar(source, value, key);
    } else if (key == "format") {
      entry.format = Scalar(source, value, key);
      if (std::find(std::begin(kFormats), std::end(kFormats), entry.format) == std::end(kFormats)) {
        Fail(source, value,
             fmt::format("format: expected carmen, rawlog, rosbag, rosbag2 or simulated, got '{}'", entry.format));
      }
    } else if (key == "path") {
      entry.path = Scalar(source, value, key);
    } else if (key == "ground_truth") {
      try {
        entry.ground_truth = ParseGroundTruthKind(Scalar(source, value, key), key);
      } catch (const InputError& error) {
        Fail(source, value, error.what());
      }
      has_ground_truth = true;
      ground_truth_node = value;
    } else if (std::string* bag_field = BagField(entry.bag, key)) {
      *bag_field = Scalar(source, value, key);
      if (bag_field->empty()) Fail(source, value, fmt::format("{}: expected a topic or frame name", key));
      bag_node = item.first;
    } else if (key == "relations") {
      entry.relations_path = Scalar(source, value, key);
    } else if (key == "reference_map") {
      entry.reference_map_path = Scalar(source, value, key);
    } else if (key == "relations_offset_s") {
      entry.relations_offset_s = Number(source, value, key);
    } else if (key == "relations_rate") {
      entry.relations_rate = Number(source, value, key);
      if (!(entry.relations_rate > 0.0)) Fail(source, value, "relations_rate: expected a clock rate > 0");
    } else if (key == "relations_window") {
      entry.relations_window_s = ParseWindow(source, value, key);
    } else if (key == "odometry") {
      try {
        entry.odometry = ParseOdometryMode(Scalar(source, value, key), "odometry");
      } catch (const InputError& error) {
        Fail(source, value, error.what());
      }
      odometry_node = value;
    } else if (key == "corrected_log") {
      entry.corrected_log = ParseCorrectedLog(source, value);
    } else if (key == "notes") {
      entry.notes = Scalar(source, value, key);
    } else if (key == "max_range_m") {
      entry.max_range_m = Number(source, value, key);
      if (!(*entry.max_range_m > 0.0)) Fail(source, value, "max_range_m: expected a range > 0 m");
    } else if (key == "stamp_policy") {
      entry.stamp_policy = Scalar(source, value, key);
      try {
        ParseStampPolicy(entry.stamp_policy, "stamp_policy");
      } catch (const InputError& error) {
        Fail(source, value, error.what());
      }
    } else if (key == "citation") {
      entry.citation = Scalar(source, value, key);
    } else if (key == "licence") {
      entry.licence_note = Scalar(source, value, key);
    } else if (key == "download") {
      entry.download_hint = Scalar(source, value, key);
    } else if (key == "simulation") {
      if (!value.IsMap()) Fail(source, value, "simulation: expected a map of generator options");
      entry.simulation = ToJson(source, value);
      try {
        SimulationOptionsFromJson(entry.simulation, "simulation");
      } catch (const InputError& error) {
        Fail(source, value, error.what());
      }
    } else {
      Fail(source, item.first,
           fmt::format("unknown key '{}' (expected name, format, path, ground_truth, relations, relations_offset_s, "
                       "relations_rate, relations_window, odometry, max_range_m, stamp_policy, citation, licence, "
                       "download, simulation, reference_map, corrected_log, notes; for bags scan_topic, "
                       "odometry_topic, odom_frame, base_frame, laser_frame, reference_topic, reference_frame)",
                       key));
    }
  }
  if (entry.name.empty()) Fail(source, node, "sequence entry without a name");
  if (entry.format.empty()) Fail(source, node, fmt::format("sequence '{}': no format", entry.name));
  if (!has_ground_truth) Fail(source, node, fmt::format("sequence '{}': no ground_truth", entry.name));
  if (entry.format == "simulated") {
    if (!entry.path.empty())
      Fail(source, node, fmt::format("sequence '{}': a simulated sequence has no path", entry.name));
    if (entry.corrected_log)
      Fail(source, node, fmt::format("sequence '{}': a simulated sequence has no corrected_log", entry.name));
  } else if (entry.path.empty()) {
    Fail(source, node, fmt::format("sequence '{}': no path", entry.name));
  }
  CheckBagKeys(source, node, entry, ground_truth_node, bag_node);
  if (entry.relations_window_s && entry.relations_path.empty()) {
    Fail(source, node, fmt::format("sequence '{}': relations_window without relations", entry.name));
  }
  if (entry.odometry == OdometryMode::kReference && !OdometryModeApplies(entry)) {
    Fail(
        source, odometry_node,
        fmt::format("sequence '{}': odometry: reference applies only to CARMEN logs whose logged pose is the corrected "
                    "pose (format carmen, ground_truth corrected_poses); this sequence has only its recorded odometry",
                    entry.name));
  }
  return entry;
}

std::filesystem::path RequireFile(const CatalogEntry& entry, std::string_view what, const std::string& path_text,
                                  const CatalogVariables& variables) {
  const std::filesystem::path path = ResolveCatalogPath(path_text, variables);
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputError(fmt::format("catalog sequence '{}': {} {} is missing{}", entry.name, what, path.string(),
                                 entry.download_hint.empty() ? "" : "; get it from: " + entry.download_hint));
  }
  return path;
}

/// The sequence's own path: a file, or a ROS 2 bag folder with all its files.
std::filesystem::path RequireSequence(const CatalogEntry& entry, const CatalogVariables& variables) {
  const std::filesystem::path path = ResolveCatalogPath(entry.path, variables);
  std::error_code error;
  if (entry.format != "rosbag2" || !std::filesystem::is_directory(path, error)) {
    return RequireFile(entry, "file", entry.path, variables);
  }
  try {
    SequenceFiles(path);
  } catch (const InputError& missing) {
    throw InputError(fmt::format("catalog sequence '{}': {}{}", entry.name, missing.what(),
                                 entry.download_hint.empty() ? "" : "; get it from: " + entry.download_hint));
  }
  return path;
}

/// The relations of a sequence whose reader takes none (a rawlog, a ROS bag): as a raw CARMEN log's, their
/// stamps (on the entry's clock once shifted) name scans, and each moves onto the scan whose stamp is
/// nearest within half the median scan spacing; relations outside the entry's window or the scans' span
/// are counted outside the log.
void AddRelationsOnScans(Sequence& sequence, const std::filesystem::path& relations_path, const CatalogEntry& entry) {
  Relations relations = ReadRelations(relations_path);
  const std::size_t read = relations.size();
  if (entry.relations_window_s) {
    // Named values, not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
    const double from_s = (*entry.relations_window_s)[0];
    const double to_s = (*entry.relations_window_s)[1];
    std::erase_if(relations, [&](const Relation& relation) {
      return std::min(relation.t1_s, relation.t2_s) < from_s || std::max(relation.t1_s, relation.t2_s) > to_s;
    });
  }
  for (Relation& relation : relations) {
    relation.t1_s = entry.relations_rate * relation.t1_s + entry.relations_offset_s;
    relation.t2_s = entry.relations_rate * relation.t2_s + entry.relations_offset_s;
  }
  std::vector<double> stamps_s;
  for (const LaserScan& scan : sequence.scans) stamps_s.push_back(scan.stamp_s);
  if (!stamps_s.empty()) {
    const auto extremes = std::minmax_element(stamps_s.begin(), stamps_s.end());
    const auto low = extremes.first;
    const auto high = extremes.second;
    std::erase_if(relations, [&](const Relation& relation) {
      return std::min(relation.t1_s, relation.t2_s) < *low || std::max(relation.t1_s, relation.t2_s) > *high;
    });
  }
  sequence.relations_outside_log += read - relations.size();
  std::size_t unmatched = 0;
  const double tolerance_s = 0.5 * MedianSpacingS(stamps_s);
  sequence.relations = MapRelationsOntoRecords(std::move(relations), stamps_s, stamps_s, tolerance_s, unmatched);
  if (unmatched > 0) {
    sequence.warnings.push_back(
        Located(relations_path, 0,
                fmt::format("{} of {} relation stamps lie farther than {:.3f} s from every scan of {} and keep their "
                            "own time",
                            unmatched, 2 * sequence.relations->size(), tolerance_s, entry.path)));
  }
}

/// The entry's provenance where the reader found none, its relations window's cut, and its relations
/// outside the log counted.
Sequence Finished(Sequence sequence, const CatalogEntry& entry) {
  if (sequence.provenance.citation.empty()) sequence.provenance.citation = entry.citation;
  if (sequence.provenance.licence_note.empty()) sequence.provenance.licence_note = entry.licence_note;
  sequence.provenance.notes = entry.notes;
  if (entry.relations_window_s) {
    const auto [from_s, to_s] = *entry.relations_window_s;
    sequence = KeepTimeSpan(std::move(sequence), entry.relations_rate * from_s + entry.relations_offset_s,
                            entry.relations_rate * to_s + entry.relations_offset_s);
  }
  KeepRelationsInsideLog(sequence);
  return sequence;
}

}  // namespace

bool OdometryModeApplies(const CatalogEntry& entry) {
  return entry.format == "carmen" && entry.ground_truth == GroundTruthKind::kCorrectedPoses;
}

bool LoggedPoseIsReference(const CatalogEntry& entry) {
  return entry.ground_truth == GroundTruthKind::kCorrectedPoses || entry.ground_truth == GroundTruthKind::kExact;
}

OdometryMode EffectiveOdometryMode(const CatalogEntry& entry) {
  return OdometryModeApplies(entry) ? entry.odometry.value_or(OdometryMode::kRecorded) : OdometryMode::kRecorded;
}

bool GroundTruthHasPoses(GroundTruthKind kind) {
  return kind == GroundTruthKind::kCorrectedPoses || kind == GroundTruthKind::kExact ||
         kind == GroundTruthKind::kMeasured;
}

std::string_view GroundTruthKindName(GroundTruthKind kind) {
  switch (kind) {
    case GroundTruthKind::kCorrectedPoses:
      return "corrected_poses";
    case GroundTruthKind::kExact:
      return "exact";
    case GroundTruthKind::kRelationsOnly:
      return "relations_only";
    case GroundTruthKind::kNone:
      return "none";
    case GroundTruthKind::kMeasured:
      return "measured";
  }
  return "none";
}

GroundTruthKind ParseGroundTruthKind(std::string_view text, std::string_view option) {
  std::string names;
  for (GroundTruthKind kind : kGroundTruthKinds) {
    if (text == GroundTruthKindName(kind)) return kind;
    names += (names.empty() ? "" : ", ") + std::string(GroundTruthKindName(kind));
  }
  throw InputError(fmt::format("{}: expected one of {}, got '{}'", option, names, text));
}

Catalog ParseCatalog(std::string_view yaml_text, const std::filesystem::path& source) {
  RequireUtf8(yaml_text, source, "a dataset catalog is UTF-8");
  YAML::Node root;
  try {
    root = YAML::Load(std::string(yaml_text));
  } catch (const YAML::Exception& error) {
    throw InputError(Located(source, static_cast<std::size_t>(error.mark.line + 1), error.msg));
  }
  if (!root.IsMap()) throw InputError(Located(source, 1, "expected a map with the key 'sequences'"));
  Catalog catalog;
  catalog.source = source;
  std::set<std::string, std::less<>> names;
  bool has_sequences = false;
  for (const auto& item : root) {
    const std::string key = KeyText(source, item.first);
    // "x-..." keys hold YAML anchors that entries share (citations, licences), as in Compose files.
    if (key.starts_with("x-")) continue;
    if (key != "sequences") {
      Fail(source, item.first, fmt::format("unknown key '{}' (expected sequences, or x-... for shared anchors)", key));
    }
    if (!item.second.IsSequence()) Fail(source, item.second, "sequences: expected a list of entries");
    has_sequences = true;
    for (const auto& node : item.second) {
      CatalogEntry entry = ParseEntry(source, node);
      if (!names.insert(entry.name).second) {
        Fail(source, node, fmt::format("sequence '{}' is listed twice", entry.name));
      }
      catalog.entries.push_back(std::move(entry));
    }
  }
  if (!has_sequences) throw InputError(Located(source, 1, "no 'sequences' list"));
  return catalog;
}

Catalog ReadCatalog(const std::filesystem::path& path) { return ParseCatalog(ReadTextFile(path), path); }

CatalogEntry ParseCatalogEntry(const std::filesystem::path& source, const YAML::Node& node) {
  return ParseEntry(source, node);
}

const CatalogEntry& FindCatalogEntry(const Catalog& catalog, std::string_view name) {
  std::string known;
  for (const CatalogEntry& entry : catalog.entries) {
    if (entry.name == name) return entry;
    known += (known.empty() ? "" : ", ") + entry.name;
  }
  throw InputError(
      fmt::format("no sequence named '{}' in the catalog {} (known: {})", name, catalog.source.string(), known));
}

std::filesystem::path ResolveCatalogPath(std::string_view path, const CatalogVariables& variables) {
  std::string resolved;
  std::size_t start = 0;
  while (true) {
    const std::size_t open = path.find("${", start);
    if (open == std::string_view::npos) break;
    const std::size_t close = path.find('}', open);
    if (close == std::string_view::npos) {
      throw InputError(fmt::format("catalog path '{}': '${{' without a closing '}}'", path));
    }
    const std::string_view name = path.substr(open + 2, close - open - 2);
    const auto found = variables.find(name);
    if (found == variables.end()) {
      throw InputError(fmt::format("catalog path '{}': unknown variable ${{{}}}", path, name));
    }
    resolved += path.substr(start, open - start);
    resolved += found->second;
    start = close + 1;
  }
  resolved += path.substr(start);
  return resolved;
}

Sequence LoadCatalogSequence(const CatalogEntry& entry, const CatalogVariables& variables) {
  Provenance provenance{"", entry.citation, entry.licence_note, entry.notes};
  if (entry.format == "simulated") {
    const SimulationOptions options = SimulationOptionsFromJson(entry.simulation, "simulation");
    SimulatedSequence simulated = SimulateSequence(options);
    Sequence sequence;
    sequence.name = entry.name;
    sequence.scans = std::move(simulated.scans);
    sequence.odometry = std::move(simulated.odometry);
    sequence.reference = std::move(simulated.ground_truth);
    sequence.reference_map = std::move(simulated.floor_plan);
    provenance.source = "slamsweep simulation " + simulated.specification.dump();
    sequence.provenance = provenance;
    return sequence;
  }
  const std::filesystem::path path = RequireSequence(entry, variables);
  SequenceReadOptions options;
  options.name = entry.name;
  options.bag = entry.bag;
  options.carmen.max_range_m = entry.max_range_m;
  options.carmen.logged_pose_is_reference = LoggedPoseIsReference(entry);
  options.carmen.relations_window_s = entry.relations_window_s;
  options.carmen.stamps.policy = ParseStampPolicy(entry.stamp_policy, "stamp_policy");
  options.carmen.odometry = EffectiveOdometryMode(entry);
  // The catalog's default falls back to the logged odometry (with a warning) where a log has no stream.
  options.carmen.require_recorded_odometry = entry.odometry.has_value();
  options.rawlog_stamps.policy = options.carmen.stamps.policy;
  std::optional<std::filesystem::path> relations_path;
  if (!entry.relations_path.empty()) {
    relations_path = RequireFile(entry, "relations file", entry.relations_path, variables);
  }
  if (entry.corrected_log) {
    // The corrected log of the same run gives the clock, the reference and the relations (on its raw scans).
    const std::filesystem::path corrected_path =
        RequireFile(entry, "corrected log", entry.corrected_log->path, variables);
    SequenceReadOptions corrected_options = options;
    corrected_options.carmen.logged_pose_is_reference = true;
    corrected_options.carmen.odometry = OdometryMode::kRecorded;
    corrected_options.carmen.require_recorded_odometry = true;
    corrected_options.carmen.relations_path = relations_path;
    corrected_options.carmen.relations_offset_s = entry.relations_offset_s;
    corrected_options.carmen.relations_rate = entry.relations_rate;
    Sequence corrected = ReadSequence(corrected_path, corrected_options);
    Sequence sequence = ReadSequence(path, options);
    TakeClockFromCorrectedLog(sequence, std::move(corrected), entry.corrected_log->first_scan,
                              entry.corrected_log->first_reading, entry.corrected_log->every, corrected_path);
    return Finished(std::move(sequence), entry);
  }
  options.carmen.relations_path = relations_path;
  options.carmen.relations_offset_s = entry.relations_offset_s;
  options.carmen.relations_rate = entry.relations_rate;
  Sequence sequence = ReadSequence(path, options);
  if (relations_path && entry.format != "carmen") AddRelationsOnScans(sequence, *relations_path, entry);
  return Finished(std::move(sequence), entry);
}

}  // namespace slamsweep::evaluator::inline catalog
