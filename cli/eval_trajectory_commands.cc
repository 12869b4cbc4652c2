// `slamsweep eval ape|rpe|relations`: flags follow evo's names with dashes.
#include <fmt/format.h>

#include <future>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <utility>

#include "cli/command.h"
#include "cli/segment_rpe_output.h"
#include "cli/text_table.h"
#include "evaluator/core/input_error.h"
#include "evaluator/formats/trajectory/relations_format.h"
#include "evaluator/formats/trajectory/trajectory_file.h"
#include "evaluator/trajectory_metrics/ape.h"
#include "evaluator/trajectory_metrics/relations_metric.h"
#include "evaluator/trajectory_metrics/rpe.h"

namespace slamsweep::cli {
namespace {

namespace ev = slamsweep::evaluator;

/// Options shared by ape and rpe: inputs, association and alignment.
struct PairOptions {
  std::string reference_path;
  std::string estimate_path;
  std::string align = "none";
  int n_to_align = -1;
  double t_max_diff_s = 0.01;
  double t_offset_s = 0.0;
  std::string pose_relation = "trans";
  std::string reference_format = "auto";
  std::string estimate_format = "auto";
  bool json = false;
};

ev::TrajectoryFormat ParseFormatOption(const std::string& format) {
  const std::optional<ev::TrajectoryFormat> parsed = ev::ParseTrajectoryFormat(format);
  if (!parsed) {
    throw ev::InputError("--ref-format/--est-format '" + format +
                         "': expected one of auto, tum, kitti, mrpt, carmen, csv");
  }
  return *parsed;
}

/// Format notes such as a CARMEN log's broken clock go to stderr so that --json output stays one object.
ev::Trajectory TrajectoryWithNotes(ev::TrajectoryFile file, const Streams& streams) {
  for (const std::string& warning : file.warnings) streams.err << "slamsweep: warning: " << warning << "\n";
  return std::move(file.trajectory);
}

/// Reads a trajectory in the given (or detected) format.
ev::Trajectory ReadForCommand(const std::string& path, const std::string& format, const Streams& streams) {
  const ev::TrajectoryFormat parsed = ParseFormatOption(format);
  return TrajectoryWithNotes(ev::ReadTrajectoryFile(path, parsed), streams);
}

/// The reference and the estimate of an ape or rpe command, read at once: the estimate on a thread of its own
/// (parsing the files is most of an eval command's time). Errors and notes come as reading one after the other
/// would give them, the reference's first.
std::pair<ev::Trajectory, ev::Trajectory> ReadPairForCommand(const PairOptions& options, const Streams& streams) {
  const ev::TrajectoryFormat reference_format = ParseFormatOption(options.reference_format);
  std::future<ev::TrajectoryFile> estimate = std::async(std::launch::async, [&options] {
    return ev::ReadTrajectoryFile(options.estimate_path, ParseFormatOption(options.estimate_format));
  });
  ev::Trajectory reference =
      TrajectoryWithNotes(ev::ReadTrajectoryFile(options.reference_path, reference_format), streams);
  return {std::move(reference), TrajectoryWithNotes(estimate.get(), streams)};
}

void AddPairOptions(CLI::App& command, PairOptions& options) {
  command.add_option("REF", options.reference_path, "reference trajectory (TUM, KITTI, CSV, CARMEN log, MRPT path)")
      ->required();
  command.add_option("EST", options.estimate_path, "estimated trajectory")->required();
  command.add_option("--align", options.align, "alignment: none|origin|se2|se3|sim2|sim3")->capture_default_str();
  command.add_option("--n-to-align", options.n_to_align, "align on the first N pairs only (-1 = all)")
      ->capture_default_str();
  command.add_option("--t-max-diff", options.t_max_diff_s, "max time difference for association (s)")
      ->capture_default_str();
  command.add_option("--t-offset", options.t_offset_s, "time offset added to EST stamps (s)")->capture_default_str();
  command.add_option("--pose-relation", options.pose_relation, "trans (m) or rot-deg (degrees)")->capture_default_str();
  command.add_option("--ref-format", options.reference_format, "auto|tum|kitti|mrpt|carmen|csv")->capture_default_str();
  command.add_option("--est-format", options.estimate_format, "auto|tum|kitti|mrpt|carmen|csv")->capture_default_str();
  command.add_flag("--json", options.json, "print one JSON object instead of a table");
}

ev::AssociationOptions ToAssociation(const PairOptions& options) {
  ev::AssociationOptions association;
  association.t_max_diff_s = options.t_max_diff_s;
  association.t_offset_s = options.t_offset_s;
  return association;
}

ev::AlignmentOptions ToAlignment(const PairOptions& options) {
  ev::AlignmentOptions alignment;
  alignment.mode = ev::ParseAlignmentMode(options.align);
  alignment.n_to_align = options.n_to_align;
  return alignment;
}

void PrintMetric(const ev::MetricResult& result, bool json, std::ostream& out) {
  const nlohmann::json j = result.ToJson();
  if (json) {
    out << j.dump() << "\n";
    return;
  }
  TextTable table(fmt::format("{} ({}) — {}", result.metric, result.unit, j.at("specification").dump()));
  const auto& s = result.statistics;
  table.Add("rmse", s.rmse);
  table.Add("mean", s.mean);
  table.Add("median", s.median);
  table.Add("std", s.std);
  table.Add("min", s.min);
  table.Add("max", s.max);
  table.Add("sse", s.sse);
  table.Add("n", std::to_string(s.n));
  table.Add("pairs", fmt::format("{} (reference unpaired {}, estimate unpaired {})", result.pairs,
                                 result.reference_unpaired, result.estimate_unpaired));
  if (result.alignment) table.Add("alignment scale", result.alignment->scale);
  table.Print(out);
}

void RegisterApe(CLI::App& eval, const Streams& streams) {
  auto options = std::make_shared<PairOptions>();
  CLI::App* command = eval.add_subcommand("ape", "absolute pose error (evo_ape)");
  AddPairOptions(*command, *options);
  command->callback([options, streams] {
    ev::ApeOptions ape_options;
    ape_options.pose_relation = ev::ParsePoseRelation(options->pose_relation);
    ape_options.association = ToAssociation(*options);
    ape_options.alignment = ToAlignment(*options);
    const auto [reference, estimate] = ReadPairForCommand(*options, streams);
    PrintMetric(ev::Ape(ape_options).Compute(reference, estimate), options->json, streams.out);
  });
}

void RegisterRpe(CLI::App& eval, const Streams& streams) {
  auto options = std::make_shared<PairOptions>();
  auto delta = std::make_shared<double>(1.0);
  auto delta_unit = std::make_shared<std::string>("f");
  auto all_pairs = std::make_shared<bool>(false);
  auto pairs_from_reference = std::make_shared<bool>(false);
  auto segments = std::make_shared<std::string>();
  CLI::App* command = eval.add_subcommand("rpe", "relative pose error (evo_rpe)");
  AddPairOptions(*command, *options);
  CLI::Option* delta_option = command->add_option("--delta", *delta, "distance between the poses of a pair");
  CLI::Option* unit_option =
      command->add_option("--delta-unit", *delta_unit, "f (frames), m (metres), s (seconds), d (degrees)");
  command->add_flag("--all-pairs", *all_pairs, "use all pairs at distance delta, not only consecutive ones");
  command->add_flag("--pairs-from-reference", *pairs_from_reference,
                    "choose the pairs on the reference, not the estimate");
  command
      ->add_option("--segments", *segments,
                   "segment RPE instead: lengths in metres (5,10,20) or auto (10-50 % of the reference path), "
                   "each as --delta L --delta-unit m --all-pairs --pairs-from-reference; reports m, % and deg/m")
      ->excludes(delta_option)
      ->excludes(unit_option);
  command->callback([options, delta, delta_unit, all_pairs, pairs_from_reference, segments, command, streams] {
    if (command->count("--segments") > 0) {
      if (options->align != "none" || command->count("--pose-relation") > 0 || *all_pairs || *pairs_from_reference) {
        throw ev::InputError(
            "--segments: give no --align, --pose-relation, --all-pairs or --pairs-from-reference; "
            "segments are chosen on the reference and report translation and rotation");
      }
      const auto [reference, estimate] = ReadPairForCommand(*options, streams);
      PrintSegmentRpe(reference, estimate, ParseSegmentsOption(*segments), ToAssociation(*options), options->json,
                      streams.out);
      return;
    }
    if (command->count("--delta") == 0 || command->count("--delta-unit") == 0) {
      throw ev::InputError("rpe: --delta and --delta-unit are required (or --segments for the segment RPE)");
    }
    ev::RpeOptions rpe_options;
    rpe_options.pairs_from_reference = *pairs_from_reference;
    rpe_options.pose_relation = ev::ParsePoseRelation(options->pose_relation);
    rpe_options.delta = *delta;
    rpe_options.delta_unit = ev::ParseDeltaUnit(*delta_unit);
    rpe_options.all_pairs = *all_pairs;
    rpe_options.association = ToAssociation(*options);
    rpe_options.alignment = ToAlignment(*options);
    const auto [reference, estimate] = ReadPairForCommand(*options, streams);
    PrintMetric(ev::Rpe(rpe_options).Compute(reference, estimate), options->json, streams.out);
  });
}

void RegisterRelations(CLI::App& eval, const Streams& streams) {
  struct Options {
    std::string trajectory_path;
    std::string relations_path;
    double t_offset_s = 0.0;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = eval.add_subcommand("relations", "Kuemmerle et al. relations metric");
  command->add_option("TRAJ", options->trajectory_path, "estimated trajectory")->required();
  command->add_option("RELATIONS", options->relations_path, "relations file (t1 t2 x y z roll pitch yaw)")->required();
  command->add_option("--t-offset", options->t_offset_s, "time offset added to relation stamps (s)")
      ->capture_default_str();
  command->add_flag("--json", options->json, "print one JSON object instead of a table");
  command->callback([options, streams] {
    ev::RelationsOptions relations_options;
    relations_options.t_offset_s = options->t_offset_s;
    // The relations file is read on a thread of its own while the trajectory is read here.
    std::future<ev::Relations> relations_read =
        std::async(std::launch::async, [options] { return ev::ReadRelations(options->relations_path); });
    const ev::Trajectory estimate = ReadForCommand(options->trajectory_path, "auto", streams);
    const ev::Relations relations = relations_read.get();
    const ev::RelationsResult result = ev::RelationsMetric(relations_options).Compute(estimate, relations);
    const nlohmann::json j = result.ToJson();
    if (options->json) {
      streams.out << j.dump() << "\n";
      return;
    }
    TextTable table("relations metric — " + j.at("specification").dump());
    for (const auto& [key, value] : j.items()) {
      if (key != "specification") table.Add(key, value.dump());
    }
    table.Print(streams.out);
  });
}

}  // namespace

void RegisterEvalTrajectoryCommands(CLI::App& eval, const Streams& streams) {
  RegisterApe(eval, streams);
  RegisterRpe(eval, streams);
  RegisterRelations(eval, streams);
}

}  // namespace slamsweep::cli
