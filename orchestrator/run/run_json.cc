#include "orchestrator/run/run_json.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string_view>
#include <utility>

#include "evaluator/core/input_error.h"
#include "evaluator/noise/json_fields.h"
#include "evaluator/catalog/catalog.h"
#include "evaluator/sequence/odometry_mode.h"
#include "evaluator/sequence/scan_stamps.h"
#include "evaluator/simulation/simulated_sequence.h"
#include "orchestrator/run/spec_checks.h"
#include "orchestrator/run/stable_hash.h"

namespace slamsweep::orchestrator::inline run {
namespace {

using evaluator::InputError;
using evaluator::JsonFields;
using nlohmann::json;

constexpr std::string_view kFile = "run.json: ";

[[noreturn]] void Fail(const std::string& path, std::string_view expected, const json& value) {
  throw InputError(std::string(kFile) + path + ": expected " + std::string(expected) + ", got " + value.dump());
}

/// Every message of this file starts with "run.json: " so the worker's exit-2 message names the file.
template <typename Function>
auto Prefixed(Function&& function) -> decltype(function()) {
  try {
    return function();
  } catch (const InputError& error) {
    const std::string_view message = error.what();
    if (message.starts_with(kFile)) throw;
    throw InputError(std::string(kFile) + std::string(message));
  }
}

std::string Join(const std::string& path, std::string_view key) { return path + "." + std::string(key); }

/// run.json writes absent optional values as null; JsonFields treats a missing field as "use the
/// default", so nulls are dropped before reading (null and absent mean the same here).
json WithoutNulls(const json& object, const std::string& path) {
  if (!object.is_object()) Fail(path, "an object", object);
  json copy = json::object();
  for (const auto& [key, value] : object.items()) {
    if (!value.is_null()) copy[key] = value;
  }
  return copy;
}

/// Removes `key` from `object` and returns it (null when absent); for the fields JsonFields has no
/// reader for (arrays, scalar maps), so that Finish() still catches unknown keys.
json Take(json& object, std::string_view key) {
  const auto found = object.find(std::string(key));
  if (found == object.end()) return nullptr;
  json value = std::move(*found);
  object.erase(found);
  return value;
}

std::vector<std::string> StringList(const json& value, const std::string& path) {
  if (!value.is_array()) Fail(path, "an array of strings", value);
  std::vector<std::string> items;
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (!value[i].is_string()) Fail(path + "[" + std::to_string(i) + "]", "a string", value[i]);
    items.push_back(value[i].get<std::string>());
  }
  return items;
}

json OptionalNumber(const std::optional<double>& value) { return value ? json(*value) : json(nullptr); }

json ToJson(const DeclaredOutput& output) { return json{{"path", output.path}, {"format", output.format}}; }

std::optional<DeclaredOutput> DeclaredOutputFromJson(const json* value, const std::string& path) {
  if (value == nullptr) return std::nullopt;
  JsonFields fields(*value, path);
  DeclaredOutput output;
  output.path = fields.Text("path", "");
  output.format = fields.Text("format", "");
  fields.Finish();
  if (output.path.empty()) throw InputError(Join(path, "path") + ": expected a non-empty path");
  if (output.format.empty()) throw InputError(Join(path, "format") + ": expected a format name");
  return output;
}

json ToJson(const CommandDeclaration& command) {
  json object = {{"argv", command.argv},
                 {"input_format", command.input_format},
                 {"trajectory", command.trajectory ? ToJson(*command.trajectory) : json(nullptr)},
                 {"map", command.map ? ToJson(*command.map) : json(nullptr)},
                 {"stage_maps", command.stage_maps_glob},
                 {"stage_unknown_value", command.stage_unknown_value}};
  // Only when declared: the command is part of the run id, which must not change for sweeps without it.
  if (!command.read_only.empty()) object["read_only"] = command.read_only;
  return object;
}

CommandDeclaration CommandFromJson(const json& value, const std::string& path) {
  json object = WithoutNulls(value, path);
  const json argv = Take(object, "argv");
  const json read_only = Take(object, "read_only");
  if (argv.is_null()) throw InputError(Join(path, "argv") + ": missing; expected an array of strings");
  CommandDeclaration command;
  command.argv = StringList(argv, Join(path, "argv"));
  if (command.argv.empty()) throw InputError(Join(path, "argv") + ": expected at least the program name");
  JsonFields fields(object, path);
  command.input_format = fields.Text("input_format", command.input_format);
  command.trajectory = DeclaredOutputFromJson(fields.Object("trajectory"), Join(path, "trajectory"));
  command.map = DeclaredOutputFromJson(fields.Object("map"), Join(path, "map"));
  command.stage_maps_glob = fields.Text("stage_maps", "");
  command.stage_unknown_value = fields.Integer("stage_unknown_value", command.stage_unknown_value);
  fields.Finish();
  if (!read_only.is_null()) command.read_only = StringList(read_only, Join(path, "read_only"));
  for (std::size_t i = 0; i < command.read_only.size(); ++i) {
    if (!std::filesystem::path(command.read_only[i]).is_absolute()) {
      throw InputError(Join(path, "read_only") + "[" + std::to_string(i) + "]: expected an absolute path, got \"" +
                       command.read_only[i] + "\"");
    }
  }
  if (command.stage_unknown_value < 0 || command.stage_unknown_value > 255) {
    throw InputError(Join(path, "stage_unknown_value") + ": expected a grey level in 0..255, got " +
                     std::to_string(command.stage_unknown_value));
  }
  return command;
}

json ToJson(const AlgorithmSpec& algorithm) {
  return json{{"name", algorithm.name},
              {"adapter", algorithm.adapter},
              {"parameters", algorithm.parameters},
              {"timeout_s", algorithm.timeout_s},
              {"memory_limit_mb", algorithm.memory_limit_mb},
              {"disk_limit_mb", algorithm.disk_limit_mb},
              {"process_limit", algorithm.process_limit},
              {"network", algorithm.network},
              {"command", algorithm.command ? ToJson(*algorithm.command) : json(nullptr)}};
}

AlgorithmSpec AlgorithmFromJson(const json& value, const std::string& path) {
  json object = WithoutNulls(value, path);
  const json parameters = Take(object, "parameters");
  JsonFields fields(object, path);
  AlgorithmSpec algorithm;
  algorithm.name = fields.Text("name", "");
  algorithm.adapter = fields.Text("adapter", "");
  algorithm.timeout_s = fields.Number("timeout_s", algorithm.timeout_s);
  algorithm.memory_limit_mb = fields.Unsigned("memory_limit_mb", algorithm.memory_limit_mb);
  algorithm.disk_limit_mb = fields.Unsigned("disk_limit_mb", algorithm.disk_limit_mb);
  algorithm.process_limit = fields.Unsigned("process_limit", algorithm.process_limit);
  algorithm.network = fields.Bool("network", algorithm.network);
  if (const json* command = fields.Object("command"))
    algorithm.command = CommandFromJson(*command, Join(path, "command"));
  fields.Finish();
  if (algorithm.name.empty()) throw InputError(Join(path, "name") + ": expected a non-empty name");
  if (algorithm.adapter.empty()) throw InputError(Join(path, "adapter") + ": expected an adapter name");
  if (!(algorithm.timeout_s > 0.0) || !std::isfinite(algorithm.timeout_s)) {
    throw InputError(Join(path, "timeout_s") + ": expected a finite number of seconds > 0");
  }
  if (algorithm.disk_limit_mb == 0) throw InputError(Join(path, "disk_limit_mb") + ": expected a number of MB >= 1");
  if (algorithm.process_limit < kMinProcessLimit) {
    throw InputError(Join(path, "process_limit") + ": expected at least " + std::to_string(kMinProcessLimit) +
                     " processes and threads");
  }
  if (!parameters.is_null()) {
    if (!parameters.is_object()) Fail(Join(path, "parameters"), "an object of scalar values", parameters);
    for (const auto& [key, parameter] : parameters.items()) {
      if (!parameter.is_primitive() || parameter.is_null()) {
        Fail(Join(Join(path, "parameters"), key), "a number, string or bool", parameter);
      }
    }
    algorithm.parameters = parameters;
  }
  return algorithm;
}

json ToJson(const NoiseSpec& noise) {
  return json{{"name", noise.name},
              {"odometry", noise.odometry ? json(*noise.odometry) : json(nullptr)},
              {"range", noise.range ? json(*noise.range) : json(nullptr)}};
}

NoiseSpec NoiseFromJson(const json& value, const std::string& path) {
  const json object = WithoutNulls(value, path);
  JsonFields fields(object, path);
  NoiseSpec noise;
  noise.name = fields.Text("name", "");
  if (const json* odometry = fields.Object("odometry")) {
    noise.odometry = evaluator::OdometryNoiseFromJson(*odometry, Join(path, "odometry"));
  }
  if (const json* range = fields.Object("range"))
    noise.range = evaluator::RangeNoiseFromJson(*range, Join(path, "range"));
  fields.Finish();
  if (noise.name.empty()) throw InputError(Join(path, "name") + ": expected a non-empty name");
  return noise;
}

json ToJson(const EvaluationOptions& evaluation) {
  return json{{"align", evaluation.align},
              {"rpe_delta_m", evaluation.rpe_delta_m},
              {"rpe_segments_m", SegmentLengthsJson(evaluation.rpe_segments_m)},
              {"t_max_diff_s", evaluation.t_max_diff_s},
              {"stages", evaluation.stages},
              {"map_resolution_m", evaluation.map_resolution_m},
              {"crop", evaluation.crop},
              {"min_coverage", evaluation.min_coverage}};
}

EvaluationOptions EvaluationFromJson(const json& value, const std::string& path) {
  json object = WithoutNulls(value, path);
  const json segments = Take(object, "rpe_segments_m");
  JsonFields fields(object, path);
  EvaluationOptions evaluation;
  ReadEvaluationFields(fields, evaluation);
  if (!segments.is_null()) evaluation.rpe_segments_m = ParseSegmentLengths(segments, Join(path, "rpe_segments_m"));
  fields.Finish();
  ValidateEvaluationOptions(evaluation, path);
  return evaluation;
}

json ToJson(const Threshold& threshold) {
  return json{{"metric", threshold.metric},
              {"statistic", threshold.statistic},
              {"max", OptionalNumber(threshold.max)},
              {"min", OptionalNumber(threshold.min)}};
}

Threshold ThresholdFromJson(const json& value, const std::string& path) {
  const json object = WithoutNulls(value, path);
  JsonFields fields(object, path);
  Threshold threshold;
  threshold.metric = fields.Text("metric", "");
  threshold.statistic = fields.Text("statistic", threshold.statistic);
  if (object.contains("max")) threshold.max = fields.Number("max", 0.0);
  if (object.contains("min")) threshold.min = fields.Number("min", 0.0);
  fields.Finish();
  ValidateThreshold(threshold, path);
  return threshold;
}

json ToJson(const SequenceSpec& sequence) {
  json out = orchestrator::ToJson(sequence.entry);
  out["max_scans"] = sequence.max_scans ? json(*sequence.max_scans) : json(nullptr);
  return out;
}

SequenceSpec SequenceFromJson(const json& value, const std::string& path) {
  json object = WithoutNulls(value, path);
  const json max_scans = Take(object, "max_scans");
  SequenceSpec sequence;
  sequence.entry = CatalogEntryFromJson(object, path);
  if (!max_scans.is_null()) {
    if (!max_scans.is_number_integer() || max_scans.get<std::int64_t>() < 1) {
      Fail(Join(path, "max_scans"), "an integer >= 1 (or null for all scans)", max_scans);
    }
    sequence.max_scans = max_scans.get<std::size_t>();
  }
  return sequence;
}

}  // namespace

json ToJson(const evaluator::CatalogEntry& entry) {
  json out{{"name", entry.name},
           {"format", entry.format},
           {"path", entry.path},
           {"ground_truth", std::string(evaluator::GroundTruthKindName(entry.ground_truth))},
           {"relations", entry.relations_path},
           {"relations_offset_s", entry.relations_offset_s},
           {"max_range_m", OptionalNumber(entry.max_range_m)},
           {"stamp_policy", entry.stamp_policy},
           {"simulation", entry.simulation.is_null() ? json(nullptr) : entry.simulation},
           {"citation", entry.citation},
           {"licence", entry.licence_note},
           {"download", entry.download_hint}};
  // Only when set: the run ids of entries without one (every run before it existed) stay the same.
  if (!entry.reference_map_path.empty()) out["reference_map"] = entry.reference_map_path;
  if (entry.relations_rate != 1.0) out["relations_rate"] = entry.relations_rate;
  if (entry.relations_window_s) out["relations_window"] = *entry.relations_window_s;
  if (entry.odometry) out["odometry"] = std::string(evaluator::OdometryModeName(*entry.odometry));
  if (entry.corrected_log) {
    out["corrected_log"] = json{{"path", entry.corrected_log->path},
                                {"first_scan", entry.corrected_log->first_scan},
                                {"first_reading", entry.corrected_log->first_reading},
                                {"every", entry.corrected_log->every}};
  }
  if (!entry.notes.empty()) out["notes"] = entry.notes;
  return out;
}

bool SameEvaluation(const json& recorded_evaluation, const EvaluationOptions& current) {
  try {
    return EvaluationFromJson(recorded_evaluation, "evaluation") == current;
  } catch (const InputError&) {
    return false;
  }
}

evaluator::CatalogEntry CatalogEntryFromJson(const json& value, const std::string& path) {
  json object = WithoutNulls(value, path);
  const json window = Take(object, "relations_window");
  JsonFields fields(object, path);
  evaluator::CatalogEntry entry;
  entry.name = fields.Text("name", "");
  entry.format = fields.Text("format", "");
  entry.path = fields.Text("path", "");
  const std::string ground_truth = fields.Text("ground_truth", "none");
  entry.relations_path = fields.Text("relations", "");
  entry.relations_offset_s = fields.Number("relations_offset_s", 0.0);
  if (object.contains("max_range_m")) entry.max_range_m = fields.Number("max_range_m", 0.0);
  entry.stamp_policy = fields.Text("stamp_policy", entry.stamp_policy);
  if (const json* simulation = fields.Object("simulation")) entry.simulation = *simulation;
  entry.citation = fields.Text("citation", "");
  entry.licence_note = fields.Text("licence", "");
  entry.download_hint = fields.Text("download", "");
  entry.reference_map_path = fields.Text("reference_map", "");
  entry.relations_rate = fields.Number("relations_rate", 1.0);
  if (object.contains("odometry")) {
    entry.odometry = evaluator::ParseOdometryMode(fields.Text("odometry", ""), Join(path, "odometry"));
  }
  if (const json* corrected = fields.Object("corrected_log")) {
    JsonFields link_fields(*corrected, Join(path, "corrected_log"));
    evaluator::CorrectedLogLink link;
    link.path = link_fields.Text("path", "");
    link.first_scan = link_fields.Unsigned("first_scan", 0);
    link.first_reading = link_fields.Unsigned("first_reading", 0);
    link.every = link_fields.Unsigned("every", 1);
    link_fields.Finish();
    if (link.path.empty()) throw InputError(Join(Join(path, "corrected_log"), "path") + ": expected the log's path");
    if (link.every == 0) throw InputError(Join(Join(path, "corrected_log"), "every") + ": expected a step >= 1");
    entry.corrected_log = link;
  }
  entry.notes = fields.Text("notes", "");
  fields.Finish();
  if (!window.is_null()) {
    if (!window.is_array() || window.size() != 2 || !window[0].is_number() || !window[1].is_number() ||
        !(window[0].get<double>() < window[1].get<double>())) {
      Fail(Join(path, "relations_window"), "[from, to] with from < to, in seconds", window);
    }
    entry.relations_window_s = std::array<double, 2>{window[0].get<double>(), window[1].get<double>()};
  }

  if (entry.name.empty()) throw InputError(Join(path, "name") + ": expected a non-empty name");
  constexpr std::string_view kFormats[] = {"carmen", "rawlog", "rosbag", "simulated"};
  if (std::find(std::begin(kFormats), std::end(kFormats), entry.format) == std::end(kFormats)) {
    throw InputError(Join(path, "format") + ": expected carmen, rawlog, rosbag or simulated, got \"" + entry.format +
                     "\"");
  }
  entry.ground_truth = evaluator::ParseGroundTruthKind(ground_truth, Join(path, "ground_truth"));
  if (entry.max_range_m && !(*entry.max_range_m > 0.0)) {
    throw InputError(Join(path, "max_range_m") + ": expected a range > 0 m");
  }
  if (!(entry.relations_rate > 0.0)) throw InputError(Join(path, "relations_rate") + ": expected a clock rate > 0");
  evaluator::ParseStampPolicy(entry.stamp_policy, Join(path, "stamp_policy"));
  if (entry.format == "simulated") {
    if (entry.simulation.is_null()) throw InputError(Join(path, "simulation") + ": a simulated sequence needs options");
    evaluator::SimulationOptionsFromJson(entry.simulation, Join(path, "simulation"));
  } else if (entry.path.empty()) {
    throw InputError(Join(path, "path") + ": expected the sequence's file");
  }
  return entry;
}

namespace {

json ToJson(const BuildIdentity& build) {
  return json{{"slamsweep_revision", build.slamsweep_revision}, {"program_files", build.program_files}};
}

BuildIdentity BuildFromJson(const json& value, const std::string& path) {
  json object = WithoutNulls(value, path);
  const json files = Take(object, "program_files");
  JsonFields fields(object, path);
  BuildIdentity build;
  build.slamsweep_revision = fields.Text("slamsweep_revision", "");
  fields.Finish();
  if (!files.is_null()) {
    if (!files.is_object()) Fail(Join(path, "program_files"), "an object of file digests", files);
    for (const auto& [file, digest] : files.items()) {
      if (!digest.is_string()) Fail(Join(Join(path, "program_files"), file), "a SHA-256 hex digest", digest);
      build.program_files[file] = digest.get<std::string>();
    }
  }
  return build;
}

Seeding SeedingFromText(const std::string& text, const std::string& path) {
  for (Seeding seeding : {Seeding::kSeeded, Seeding::kDeterministic, Seeding::kUnseeded}) {
    if (text == SeedingName(seeding)) return seeding;
  }
  throw InputError(path + ": expected seeded, deterministic or unseeded, got \"" + text + "\"");
}

json ToJson(const ComparisonGroup& group) {
  return json{{"sequence", group.sequence},
              {"algorithm", group.algorithm},
              {"parameters", group.parameters},
              {"noise", group.noise},
              {"odometry", group.odometry}};
}

}  // namespace

json ToJson(const RunSpec& spec) {
  json thresholds = json::array();
  for (const Threshold& threshold : spec.thresholds) thresholds.push_back(ToJson(threshold));
  return json{{"run_id", spec.run_id},
              {"group", ToJson(ComparisonGroupOf(spec))},
              {"build", ToJson(spec.build)},
              {"seeding", SeedingName(spec.seeding)},
              {"seeded", spec.seeding != Seeding::kUnseeded},
              {"odometry_is_reference", spec.odometry_is_reference},
              {"allow_unisolated", spec.allow_unisolated},
              {"sweep", spec.sweep},
              {"algorithm", ToJson(spec.algorithm)},
              {"sequence", ToJson(spec.sequence)},
              {"noise", ToJson(spec.noise)},
              {"iteration", spec.iteration},
              {"seed", spec.seed},
              {"evaluation", ToJson(spec.evaluation)},
              {"thresholds", thresholds}};
}

RunSpec RunSpecFromJson(const json& value) {
  return Prefixed([&] {
    if (!value.is_object()) Fail("(top level)", "an object", value);
    json object = value;
    const json thresholds = Take(object, "thresholds");
    // Derived from the other fields (ComparisonGroupOf, seeding): written for readers, not read back.
    Take(object, "group");
    Take(object, "seeded");
    const json build = Take(object, "build");
    JsonFields fields(object, "");
    RunSpec spec;
    spec.run_id = fields.Text("run_id", "");
    spec.sweep = fields.Text("sweep", "");
    const json* algorithm = fields.Object("algorithm");
    const json* sequence = fields.Object("sequence");
    const json* noise = fields.Object("noise");
    const json* evaluation = fields.Object("evaluation");
    spec.iteration = fields.Integer("iteration", 0);
    spec.seed = fields.Unsigned("seed", 0);
    const std::string seeding = fields.Text("seeding", std::string(SeedingName(spec.seeding)));
    spec.odometry_is_reference = fields.Bool("odometry_is_reference", false);
    spec.allow_unisolated = fields.Bool("allow_unisolated", false);
    fields.Finish();
    spec.seeding = SeedingFromText(seeding, "seeding");
    if (!build.is_null()) spec.build = BuildFromJson(build, "build");
    if (spec.run_id.empty()) throw InputError("run_id: expected a non-empty run id");
    if (algorithm == nullptr) throw InputError("algorithm: missing");
    if (sequence == nullptr) throw InputError("sequence: missing");
    if (noise == nullptr) throw InputError("noise: missing");
    if (!object.contains("seed")) throw InputError("seed: missing");
    if (spec.iteration < 0) throw InputError("iteration: expected an integer >= 0");
    spec.algorithm = AlgorithmFromJson(*algorithm, "algorithm");
    spec.sequence = SequenceFromJson(*sequence, "sequence");
    spec.noise = NoiseFromJson(*noise, "noise");
    if (evaluation != nullptr) spec.evaluation = EvaluationFromJson(*evaluation, "evaluation");
    if (!thresholds.is_null()) {
      if (!thresholds.is_array()) Fail("thresholds", "an array", thresholds);
      for (std::size_t i = 0; i < thresholds.size(); ++i) {
        spec.thresholds.push_back(ThresholdFromJson(thresholds[i], "thresholds[" + std::to_string(i) + "]"));
      }
    }
    return spec;
  });
}

int AdapterRevision(const std::string& adapter) {
  // A revision names the built-in settings an adapter's runs are computed with; raise it when they change.
  // Revision 2: mrpt-icp-slam matches against a points map and inserts densely (mrpt_settings.h), odometry
  // renders free space at p = 0.01, mrpt-rbpf-slam is seeded through RANDOM_SEED.
  if (adapter == "mrpt-icp-slam" || adapter == "odometry" || adapter == "mrpt-rbpf-slam") return 2;
  return 1;
}

json RunIdentity(const RunSpec& spec) {
  json sequence = ToJson(spec.sequence);
  // Descriptive texts do not change what a run computes; editing a citation must not re-run a sweep.
  sequence.erase("citation");
  sequence.erase("licence");
  sequence.erase("download");
  // Nor does what a run is scored against (like `evaluation`): the reference map is never the program's input.
  sequence.erase("reference_map");
  sequence.erase("notes");
  // The odometry mode as it takes effect: "recorded" on a corrected CARMEN log (the catalog's default
  // or set) changes the program's input; elsewhere the odometry is the recorded one whatever is
  // written, and reference mode is what every run computed before the mode existed, so neither
  // changes an id.
  sequence.erase("odometry");
  if (evaluator::OdometryModeApplies(spec.sequence.entry) &&
      evaluator::EffectiveOdometryMode(spec.sequence.entry) == evaluator::OdometryMode::kRecorded) {
    sequence["odometry"] = "recorded";
  }
  const json algorithm = ToJson(spec.algorithm);
  json algorithm_identity = {{"name", algorithm["name"]},
                             {"adapter", algorithm["adapter"]},
                             {"parameters", algorithm["parameters"]},
                             {"command", algorithm["command"]}};
  // Only from revision 2 on, so that the ids of runs whose adapter never changed stay the same.
  if (const int revision = AdapterRevision(spec.algorithm.adapter); revision > 1) {
    algorithm_identity["adapter_revision"] = revision;
  }
  return json{{"algorithm", std::move(algorithm_identity)},
              {"sequence", sequence},
              {"noise", ToJson(spec.noise)},
              {"iteration", spec.iteration},
              {"seed", spec.seed}};
}

std::string BuildSignatureOfRunJson(const json& run_json) {
  if (!run_json.is_object() || !run_json.contains("build") || !run_json.at("build").is_object()) return "";
  try {
    return BuildSignature(BuildFromJson(run_json.at("build"), "build"));
  } catch (const InputError&) {
    return "";
  }
}

std::string OdometryModeOfRunJson(const json& run_json) {
  const auto string_at = [&](const char* outer, const char* inner) -> const json* {
    if (!run_json.is_object()) return nullptr;
    const auto found = run_json.find(outer);
    if (found == run_json.end() || !found->is_object()) return nullptr;
    const auto value = found->find(inner);
    return value != found->end() && value->is_string() ? &*value : nullptr;
  };
  if (const json* planned = string_at("group", "odometry")) return planned->get<std::string>();
  const json* format = string_at("sequence", "format");
  const json* ground_truth = string_at("sequence", "ground_truth");
  if (format == nullptr || ground_truth == nullptr) return std::string(kOdometryUnknown);
  const bool mode_applies = *format == "carmen" && *ground_truth == evaluator::GroundTruthKindName(
                                                                        evaluator::GroundTruthKind::kCorrectedPoses);
  if (!mode_applies) return std::string(evaluator::OdometryModeName(evaluator::OdometryMode::kRecorded));
  // A corrected log: a mode written into the sequence counts; without one the run predates the mode, when
  // programs were given the logged (corrected) pose.
  if (const json* written = string_at("sequence", "odometry")) return written->get<std::string>();
  return std::string(evaluator::OdometryModeName(evaluator::OdometryMode::kReference));
}

std::string BuildDescriptionOfRunJson(const json& run_json) {
  if (!run_json.is_object() || !run_json.contains("build") || !run_json.at("build").is_object()) return "not recorded";
  try {
    const BuildIdentity build = BuildFromJson(run_json.at("build"), "build");
    std::string text = "slamsweep " + build.slamsweep_revision;
    std::string files;
    for (const auto& [path, digest] : build.program_files) {
      files += fmt::format("{}{} {}", files.empty() ? "" : ", ", std::filesystem::path(path).filename().string(),
                           digest.substr(0, 12));
    }
    return files.empty() ? text : text + "; " + files;
  } catch (const InputError&) {
    return "unreadable";
  }
}

std::optional<RunStatus> StatusOfResultJson(const json& result) {
  if (!result.is_object()) return std::nullopt;
  const auto status = result.find("status");
  if (status == result.end()) return RunStatus::kFailed;
  return status->is_string() ? RecordedRunStatus(status->get_ref<const std::string&>()) : std::nullopt;
}

}  // namespace slamsweep::orchestrator::inline run
