#include "orchestrator/adapters/command_adapter.h"

#include <filesystem>
#include <utility>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/image8.h"
#include "evaluator/formats/map/image_file.h"
#include "evaluator/formats/trajectory/trajectory_format.h"
#include "evaluator/sequence_io/robot_log_file.h"
#include "orchestrator/adapters/mrpt_ini.h"
#include "orchestrator/adapters/output_files.h"
#include "orchestrator/adapters/rendered_map.h"
#include "orchestrator/run/run_failure.h"
#include "orchestrator/adapters/stage_image.h"
#include "orchestrator/config/placeholders.h"
#include "orchestrator/config/program_path.h"
#include "orchestrator/matrix/seed_fold.h"

namespace slamsweep::orchestrator::inline adapters {

namespace ev = slamsweep::evaluator;
namespace fs = std::filesystem;

namespace {

const CommandDeclaration& Declaration(const RunSpec& spec) {
  if (!spec.algorithm.command) {
    throw ev::InputError(
        "algorithm.command: the command adapter needs a command declaration (argv, input_format, "
        "trajectory and/or map)");
  }
  const CommandDeclaration& declaration = *spec.algorithm.command;
  if (declaration.argv.empty() || declaration.argv.front().empty()) {
    throw ev::InputError("algorithm.command.argv: expected the program and its arguments, got no program");
  }
  if (!declaration.trajectory && !declaration.map) {
    throw ev::InputError("algorithm.command: declares neither a trajectory nor a map output: nothing to score");
  }
  return declaration;
}

PlaceholderValues Values(const RunSpec& spec, const RunPaths& paths) {
  PlaceholderValues values;
  const CommandDeclaration& declaration = Declaration(spec);
  const ev::SequenceWriteFormat format =
      ev::ParseSequenceWriteFormat(declaration.input_format, "algorithm.command.input_format");
  values.input = (paths.InputDir() /
                  (SafeFileStem(spec.sequence.entry.name) + InputExtension(ev::SequenceWriteFormatName(format))))
                     .string();
  values.input_dir = paths.InputDir().string();
  values.output_dir = paths.RawDir().string();
  values.seed = std::to_string(spec.seed);
  values.seed32 = std::to_string(Seed32(spec.seed));
  values.iteration = std::to_string(spec.iteration);
  values.parameters = spec.algorithm.parameters;
  return values;
}

/// A declared output file: its path expanded, relative to raw/, and not escaping the run folder.
fs::path OutputPath(const DeclaredOutput& output, const PlaceholderValues& values, const RunPaths& paths,
                    const std::string& field) {
  const fs::path relative = ExpandPlaceholders(output.path, values, field + ".path");
  const fs::path file = (paths.RawDir() / relative).lexically_normal();
  const fs::path inside = file.lexically_relative(paths.RawDir().lexically_normal());
  if (relative.is_absolute() || inside.empty() || inside.begin()->string() == "..") {
    throw ev::InputError(field + ".path: '" + output.path + "' must stay inside the run's raw/ folder");
  }
  return file;
}

ev::TrajectoryFormat TrajectoryFormatOf(const std::string& name) {
  const auto format = ev::ParseTrajectoryFormat(name);
  if (!format || *format == ev::TrajectoryFormat::kAuto) {
    throw ev::InputError("algorithm.command.trajectory.format: expected tum, kitti, csv, mrpt or carmen, got '" + name +
                         "'");
  }
  return *format;
}

ev::MapFormat MapFormatOf(const std::string& name) {
  if (name == "map_server") return ev::MapFormat::kRosMapServer;
  if (name == "mrpt") return ev::MapFormat::kMrptGridmap;
  if (name == "pgm" || name == "png") return ev::MapFormat::kBareImage;
  throw ev::InputError("algorithm.command.map.format: expected map_server, mrpt or pgm, got '" + name + "'");
}

}  // namespace

PreparedRun CommandAdapter::Prepare(const RunSpec& spec, const ev::RobotLog& robot, const RunPaths& paths) const {
  const CommandDeclaration& declaration = Declaration(spec);
  const PlaceholderValues values = Values(spec, paths);
  // Expanded before anything is written: a bad declaration leaves no half-prepared run.
  PreparedRun prepared;
  for (std::size_t i = 0; i < declaration.argv.size(); ++i) {
    prepared.argv.push_back(
        ExpandPlaceholders(declaration.argv[i], values, "algorithm.command.argv[" + std::to_string(i) + "]"));
  }
  if (declaration.trajectory) {
    OutputPath(*declaration.trajectory, values, paths, "algorithm.command.trajectory");
    TrajectoryFormatOf(declaration.trajectory->format);
  }
  if (declaration.map) {
    OutputPath(*declaration.map, values, paths, "algorithm.command.map");
    MapFormatOf(declaration.map->format);
  }
  fs::create_directories(paths.InputDir());
  fs::create_directories(paths.RawDir());
  ev::WriteRobotLog(robot, values.input,
                    ev::ParseSequenceWriteFormat(declaration.input_format, "algorithm.command.input_format"));
  return prepared;
}

std::vector<fs::path> CommandAdapter::ProgramReads(const RunSpec& spec) const {
  std::vector<fs::path> reads;
  if (spec.algorithm.command)
    reads.assign(spec.algorithm.command->read_only.begin(), spec.algorithm.command->read_only.end());
  return reads;
}

CollectedOutputs CommandAdapter::Collect(const RunSpec& spec, const ev::RobotLog& robot, const RunPaths& paths) const {
  const CommandDeclaration& declaration = Declaration(spec);
  const PlaceholderValues values = Values(spec, paths);
  CollectedOutputs outputs;

  if (declaration.trajectory) {
    const ev::TrajectoryFormat format = TrajectoryFormatOf(declaration.trajectory->format);
    ev::TrajectoryReadOptions options;
    if (format == ev::TrajectoryFormat::kMrptPath) options.mrpt_step_stamps_s = ScanStamps(robot.scans);
    outputs.trajectory =
        ReadTrajectoryOutput(paths, OutputPath(*declaration.trajectory, values, paths, "algorithm.command.trajectory"),
                             format, options, outputs.warnings);
  }

  const bool stages_from_glob = !declaration.stage_maps_glob.empty();
  if (declaration.map) {
    ev::MapReadOptions options;
    options.format = MapFormatOf(declaration.map->format);
    if (options.format == ev::MapFormat::kBareImage) options.unknown_value = declaration.stage_unknown_value;
    outputs.map =
        ReadMapOutput(paths, OutputPath(*declaration.map, values, paths, "algorithm.command.map"), "map", options);
    if (!stages_from_glob && outputs.trajectory && spec.evaluation.stages > 0) {
      try {
        outputs.stages = RenderMapFromTrajectory(robot.scans, *outputs.trajectory, spec.evaluation).stages;
      } catch (const ev::InputError& error) {
        outputs.warnings.push_back(std::string("no stage maps: ") + error.what());
      }
    }
  } else {
    // Declaration() guarantees a trajectory here. Scans outside its time span cannot be placed.
    RenderedMap rendered;
    try {
      rendered = RenderMapFromTrajectory(robot.scans, *outputs.trajectory, spec.evaluation);
    } catch (const ev::InputError& error) {
      throw RunFailure(FailureKind::kCorruptOutput,
                       std::string("no map can be rendered from the trajectory: ") + error.what());
    }
    outputs.map = std::move(rendered.grid);
    outputs.map_rendered_from_trajectory = true;
    if (!stages_from_glob) outputs.stages = std::move(rendered.stages);
    if (rendered.scans_outside_trajectory > 0) {
      outputs.warnings.push_back(std::to_string(rendered.scans_outside_trajectory) +
                                 " scans lie outside the trajectory's time span and are not in the rendered map");
    }
  }

  if (stages_from_glob) {
    for (const fs::path& file : GlobFiles(paths.RawDir(), declaration.stage_maps_glob)) {
      try {
        const cv::Mat image = ev::ReadGreyImageFile(file);
        outputs.stages.push_back(StageImage(
            ev::FromImage8(image, declaration.stage_unknown_value, outputs.map.resolution_m, outputs.map.origin)));
      } catch (const ev::InputError& error) {
        throw RunFailure(FailureKind::kCorruptOutput, std::string("corrupt stage map: ") + error.what());
      }
    }
    if (outputs.stages.empty()) {
      outputs.warnings.push_back("no stage maps: nothing under raw/ matches '" + declaration.stage_maps_glob + "'");
    }
  }
  return outputs;
}

}  // namespace slamsweep::orchestrator::inline adapters
