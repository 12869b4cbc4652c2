// `slamsweep data ...`: sequences in, SLAM-ready inputs out.
#include <fmt/format.h>

#include <charconv>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/data_sources.h"
#include "cli/scan_spacing_output.h"
#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/formats/trajectory/output_file.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "evaluator/occupancy_mapping/occupancy_mapper.h"
#include "evaluator/noise/odometry_noise.h"
#include "evaluator/noise/random.h"
#include "evaluator/noise/range_noise.h"
#include "evaluator/formats/trajectory/carmen_log.h"
#include "evaluator/formats/trajectory/relations_format.h"
#include "evaluator/sequence/carmen_sequence.h"
#include "evaluator/sequence/odometry_mode.h"
#include "evaluator/sequence/recorded_odometry.h"
#include "evaluator/sequence/relations_clock.h"
#include "evaluator/sequence/scan_spacing.h"
#include "evaluator/sequence_io/bag_trajectory_file.h"
#include "evaluator/sequence_io/sequence_file.h"
#include "evaluator/sequence_io/robot_log_file.h"
#include "evaluator/simulation/simulated_sequence.h"

namespace slamsweep::cli {

namespace ev = slamsweep::evaluator;

namespace {

/// "a,b,c" as numbers; `option` and the expected layout name the problem.
std::vector<double> NumberList(const std::string& text, const std::string& option, std::size_t min_count,
                               std::size_t max_count, const std::string& layout) {
  std::vector<double> values;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    double value = 0.0;
    const char* first = text.data() + start;
    const char* last = text.data() + end;
    const auto [stop, error] = std::from_chars(first, last, value);
    if (error != std::errc() || stop != last || first == last) {
      throw ev::InputError(option + ": expected " + layout + ", got '" + text + "'");
    }
    values.push_back(value);
    start = end + 1;
  }
  if (values.size() < min_count || values.size() > max_count) {
    throw ev::InputError(option + ": expected " + layout + ", got " + std::to_string(values.size()) + " values in '" +
                         text + "'");
  }
  return values;
}

/// The options that say how to read a sequence file, shared by every data command.
struct SourceOptions {
  std::string source;
  std::string catalog;
  evaluator::SequenceReadOptions read;
  std::string odometry;
  std::string ground_truth;
};

void AddSourceOptions(CLI::App& command, SourceOptions& options) {
  command
      .add_option("SOURCE", options.source,
                  "sequence (CARMEN log, rawlog, ROS 1 bag, ROS 2 bag folder or .db3/.mcap file) or catalog name")
      ->required();
  command.add_option("--catalog", options.catalog, "dataset catalog (default: configs/datasets.yaml)");
  ev::BagChoices& bag = options.read.bag;
  command.add_option("--scan-topic", bag.scan_topic,
                     "ROS bags: the sensor_msgs/LaserScan topic (default: the only one)");
  command.add_option("--odometry-topic", bag.odometry_topic,
                     "ROS bags: the nav_msgs/Odometry topic (default: the only one, else /tf odom -> base_link)");
  command.add_option("--odom-frame", bag.odom_frame,
                     "ROS bags: odometry from /tf this frame -> base frame (default odom)");
  command.add_option("--base-frame", bag.base_frame, "ROS bags: the robot's frame (default base_link)");
  command.add_option("--laser-frame", bag.laser_frame,
                     "ROS bags: the laser's frame for its mount in /tf_static (default: each scan's header.frame_id)");
  command.add_option("--reference-topic", bag.reference_topic,
                     "ROS bags: a reference recorded with the data: nav_msgs/Odometry, geometry_msgs/PoseStamped or "
                     "PoseWithCovarianceStamped");
  command.add_option("--reference-frame", bag.reference_frame,
                     "ROS bags: a reference from /tf: the base frame's pose in this frame (e.g. map)");
  command
      .add_option("--odometry", options.odometry,
                  "recorded | reference: the robot's odometry rebuilt from a corrected log's ODOM stream (an error "
                  "where there is none), or the logged odometry, which in a corrected log is the reference "
                  "(default: recorded where the log has the stream)")
      ->check(CLI::IsMember({"recorded", "reference"}));
  command.add_option("--ground-truth", options.ground_truth,
                     "corrected_poses | exact | relations_only | none: the sequence's reference (a catalog entry's is "
                     "replaced). A CARMEN log under relations_only or none is raw: its logged pose is the robot's "
                     "odometry, and there is no reference trajectory (default for a CARMEN file: corrected_poses, "
                     "the logged pose is the reference)");
}

ev::Sequence LoadSource(const SourceOptions& options) {
  std::optional<ev::OdometryMode> odometry;
  if (!options.odometry.empty()) odometry = ev::ParseOdometryMode(options.odometry, "--odometry");
  std::optional<ev::GroundTruthKind> ground_truth;
  if (!options.ground_truth.empty()) ground_truth = ev::ParseGroundTruthKind(options.ground_truth, "--ground-truth");
  return LoadSequenceArgument(options.source, FindCatalog(options.catalog), options.read, odometry, ground_truth);
}

nlohmann::json InfoJson(const ev::Sequence& sequence) {
  std::set<std::size_t> beam_counts;
  for (const ev::LaserScan& scan : sequence.scans) beam_counts.insert(scan.BeamCount());
  nlohmann::json info;
  info["name"] = sequence.name;
  info["scans"] = sequence.scans.size();
  if (beam_counts.size() == 1) {
    info["beams"] = *beam_counts.begin();
  } else {
    info["beams"] = std::vector<std::size_t>(beam_counts.begin(), beam_counts.end());
  }
  info["duration_s"] = sequence.scans.empty() ? 0.0 : sequence.scans.back().stamp_s - sequence.scans.front().stamp_s;
  info["has_reference"] = sequence.reference.has_value();
  // Recorded odometry: what the robot measured, not the reference (a corrected log read with its
  // logged odometry is not); the readings are the robot's whole stream, or one per scan.
  const bool recorded = !ev::OdometryEqualsReference(sequence);
  info["odometry"] = recorded ? "recorded" : "reference";
  info["recorded_odometry"] = recorded;
  info["recorded_odometry_readings"] =
      !recorded ? 0
                : (sequence.odometry_readings.empty() ? sequence.odometry.size() : sequence.odometry_readings.size());
  info["relations"] = sequence.relations ? sequence.relations->size() : 0;
  info["relations_outside_log"] = sequence.relations_outside_log;
  if (sequence.stamp_facts) info["stamps"] = ev::StampFactsJson(*sequence.stamp_facts);
  const std::optional<ev::ScanSpacing> spacing = ev::ComputeScanSpacing(sequence);
  info["scan_spacing"] = spacing ? ev::ScanSpacingJson(*spacing) : nlohmann::json();
  info["warnings"] = sequence.warnings;
  info["provenance"] = {{"source", sequence.provenance.source},
                        {"citation", sequence.provenance.citation},
                        {"licence_note", sequence.provenance.licence_note}};
  if (!sequence.provenance.notes.empty()) info["notes"] = sequence.provenance.notes;
  return info;
}

void RegisterInfo(CLI::App& data, const Streams& streams) {
  struct Options {
    SourceOptions input;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = data.add_subcommand("info", "scans, beams, duration and ground truth of a sequence");
  AddSourceOptions(*command, options->input);
  command->add_flag("--json", options->json, "print one JSON object");
  command->callback([options, streams] {
    const ev::Sequence sequence = LoadSource(options->input);
    const nlohmann::json info = InfoJson(sequence);
    if (options->json) {
      streams.out << info.dump() << "\n";
      return;
    }
    for (const auto& [key, value] : info.items()) {
      if (key != "scan_spacing") streams.out << key << ": " << value.dump() << "\n";
    }
    PrintScanSpacing(ev::ComputeScanSpacing(sequence), streams.out);
  });
}

void RegisterConvert(CLI::App& data, const Streams& streams) {
  struct Options {
    SourceOptions input;
    std::string to;
    std::string output;
    std::string odometry_noise;
    double drift_rad_per_m = 0.0;
    std::string range_noise;
    std::uint64_t seed = 1;
    std::string reference_out;
    std::string storage = "mcap";
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = data.add_subcommand(
      "convert",
      "write a sequence for SLAM programs, optionally with noise; or a trajectory in a bag (BAG:TOPIC, "
      "BAG:/tf:PARENT.CHILD) as TUM");
  AddSourceOptions(*command, options->input);
  command
      ->add_option("--to", options->to,
                   "rawlog | carmen | tum | rosbag2 (a bag folder: /scan, /odom, /tf, /tf_static, and the reference "
                   "as /ground_truth)")
      ->required();
  command->add_option("-o,--output", options->output, "output file (rosbag2: a new folder)")->required();
  command->add_option("--storage", options->storage, "rosbag2: mcap (default) or sqlite3 (ROS 2 Humble's schema)")
      ->check(CLI::IsMember({"mcap", "sqlite3"}));
  command->add_option("--odometry-noise", options->odometry_noise,
                      "alpha1,alpha2,alpha3,alpha4 of the odometry motion model (variances per step)");
  command->add_option("--drift", options->drift_rad_per_m, "systematic heading drift (rad per metre travelled)");
  command->add_option("--range-noise", options->range_noise,
                      "sigma_m[,dropout_probability[,short_reading_probability]]");
  command->add_option("--seed", options->seed,
                      "noise seed (odometry: DeriveSeed(seed, 0), ranges: DeriveSeed(seed, 1))");
  command->add_option("--reference-out", options->reference_out,
                      "also write the reference trajectory (TUM) here; keep it away from the SLAM program");
  command->callback([options, streams] {
    const ev::SequenceWriteFormat format = ev::ParseSequenceWriteFormat(options->to, "--to");
    std::error_code error;
    if (!std::filesystem::exists(options->input.source, error) && ev::NamesBagTrajectory(options->input.source)) {
      if (format != ev::SequenceWriteFormat::kTum) {
        throw ev::InputError(options->input.source + ": a trajectory in a bag converts --to tum only");
      }
      std::vector<std::string> warnings;
      const ev::Trajectory trajectory = ev::ReadBagTrajectoryArgument(options->input.source, warnings);
      for (const std::string& warning : warnings) streams.err << "slamsweep: warning: " << warning << "\n";
      ev::WriteTum(trajectory, options->output);
      streams.out << "wrote " << options->output << " (" << trajectory.size() << " poses)\n";
      return;
    }
    ev::Sequence sequence = LoadSource(options->input);

    ev::OdometryNoise odometry_noise;
    if (!options->odometry_noise.empty()) {
      const std::vector<double> alphas =
          NumberList(options->odometry_noise, "--odometry-noise", 4, 4, "alpha1,alpha2,alpha3,alpha4");
      odometry_noise.alpha1 = alphas[0];
      odometry_noise.alpha2 = alphas[1];
      odometry_noise.alpha3 = alphas[2];
      odometry_noise.alpha4 = alphas[3];
    }
    odometry_noise.drift_heading_rad_per_m = options->drift_rad_per_m;
    ev::ValidateOdometryNoise(odometry_noise);
    ev::RangeNoise range_noise;
    if (!options->range_noise.empty()) {
      const std::vector<double> values = NumberList(options->range_noise, "--range-noise", 1, 3,
                                                    "sigma_m[,dropout_probability[,short_reading_probability]]");
      range_noise.sigma_m = values[0];
      if (values.size() > 1) range_noise.dropout_probability = values[1];
      if (values.size() > 2) range_noise.short_reading_probability = values[2];
    }
    ev::ValidateRangeNoise(range_noise);

    // Noisy odometry is drawn around the ground truth when there is one: the corrected logs'
    // odometry equals their reference, and a SLAM program given it would have nothing to do.
    // On recorded odometry the noise comes on top of what the robot measured.
    const bool noisy_odometry = odometry_noise != ev::OdometryNoise{};
    const bool around_reference = ev::OdometryEqualsReference(sequence);
    if (noisy_odometry) {
      const ev::Trajectory clean = around_reference ? *sequence.reference : sequence.odometry;
      sequence.odometry = ev::ApplyOdometryNoise(clean, odometry_noise, ev::DeriveSeed(options->seed, 0));
      if (!sequence.odometry_readings.empty()) {
        sequence.odometry_readings = ev::NoisyReadings(sequence.odometry_readings, clean, sequence.odometry);
      }
    }
    if (range_noise != ev::RangeNoise{}) {
      sequence.scans = ev::ApplyRangeNoise(sequence.scans, range_noise, ev::DeriveSeed(options->seed, 1));
    }
    // Only scans and odometry go into a program's input; the reference goes to its own file, on request.
    // A ROS 2 bag is a dataset for ROS 2 tools: it carries the reference as /ground_truth.
    if (format == ev::SequenceWriteFormat::kRosbag2) {
      ev::WriteRosbag2Folder(ev::RobotLogOf(sequence), sequence.reference, options->output,
                             ev::ParseRosbag2Storage(options->storage));
    } else {
      ev::WriteRobotLog(ev::RobotLogOf(sequence), options->output, format);
    }
    if (!options->reference_out.empty()) {
      if (!sequence.reference) {
        throw ev::InputError(options->input.source + ": --reference-out: the sequence has no reference trajectory");
      }
      ev::WriteTum(*sequence.reference, options->reference_out);
    }

    nlohmann::json record;
    record["source"] = options->input.source;
    record["format"] = ev::SequenceWriteFormatName(format);
    record["seed"] = options->seed;
    record["odometry_noise"] = odometry_noise;
    record["odometry_noise_seed"] = ev::DeriveSeed(options->seed, 0);
    record["odometry_noise_around"] = !noisy_odometry ? "none" : around_reference ? "reference" : "odometry";
    record["odometry"] = around_reference ? "reference" : "recorded";
    record["range_noise"] = range_noise;
    record["range_noise_seed"] = ev::DeriveSeed(options->seed, 1);
    const std::filesystem::path noise_path = options->output + ".noise.json";
    ev::WriteOutputFile(noise_path, [&](std::ostream& out) { out << record.dump(2) << "\n"; });
    streams.out << "wrote " << options->output << " (" << sequence.scans.size() << " scans"
                << (format == ev::SequenceWriteFormat::kRosbag2 && sequence.reference ? ", reference as /ground_truth"
                                                                                      : "")
                << ") and " << noise_path.string() << "\n";
  });
}

void RegisterMap(CLI::App& data, const Streams& streams) {
  struct Options {
    SourceOptions input;
    std::string output;
    double resolution_m = 0.05;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = data.add_subcommand("map", "reference map of a sequence from its reference poses");
  AddSourceOptions(*command, options->input);
  command->add_option("-o,--output", options->output, "map_server YAML (the PGM is written beside it)")->required();
  command->add_option("--resolution", options->resolution_m, "cell size in metres");
  command->callback([options, streams] {
    const ev::Sequence sequence = LoadSource(options->input);
    if (!sequence.reference) {
      throw ev::InputError(options->input.source + ": the sequence has no reference trajectory to build a map from");
    }
    ev::OccupancyMapperOptions mapper_options;
    mapper_options.resolution_m = options->resolution_m;
    const ev::OccupancyMapper mapper(mapper_options);
    const ev::TrajectoryMap map = mapper.Build(sequence.scans, *sequence.reference);
    ev::WriteMapServer(map.grid, options->output);
    streams.out << "wrote " << options->output << " (" << map.grid.width << " x " << map.grid.height << " cells, "
                << map.scans_used << " scans";
    if (map.scans_outside_trajectory > 0)
      streams.out << ", " << map.scans_outside_trajectory << " outside the reference";
    streams.out << ")\n";
  });
}

ev::Trajectory FirstPoses(const ev::Trajectory& trajectory, std::size_t count) {
  const auto end = static_cast<std::ptrdiff_t>(count);
  return ev::Trajectory(std::vector<double>(trajectory.stamps_s().begin(), trajectory.stamps_s().begin() + end),
                        std::vector<ev::Pose>(trajectory.poses().begin(), trajectory.poses().begin() + end));
}

void RegisterSimulate(CLI::App& data, const Streams& streams) {
  struct Options {
    std::string output_dir;
    std::uint64_t seed = 1;
    std::uint64_t floor_seed = 1;
    std::optional<std::size_t> scans;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = data.add_subcommand("simulate", "generate a floor plan and a sequence with exact ground truth");
  command->add_option("-o,--output", options->output_dir, "output folder (created)")->required();
  command->add_option("--seed", options->seed, "noise seed (range and odometry noise)");
  command->add_option("--floor-seed", options->floor_seed, "floor plan seed (the layout)");
  command->add_option("--scans", options->scans, "keep only the first N scans")->check(CLI::PositiveNumber);
  command->callback([options, streams] {
    ev::SimulationOptions simulation;
    simulation.noise_seed = options->seed;
    simulation.floor_plan.seed = options->floor_seed;
    ev::SimulatedSequence simulated = ev::SimulateSequence(simulation);

    ev::Sequence sequence;
    sequence.name = "simulated";
    std::size_t count = simulated.scans.size();
    if (options->scans && *options->scans < count) count = *options->scans;
    sequence.scans.assign(simulated.scans.begin(), simulated.scans.begin() + static_cast<std::ptrdiff_t>(count));
    sequence.odometry = FirstPoses(simulated.odometry, count);
    sequence.reference = FirstPoses(simulated.ground_truth, count);
    sequence.provenance = {"slamsweep simulation", "slamsweep's floor-plan simulator", "generated data", ""};

    const std::filesystem::path dir = options->output_dir;
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) throw ev::InputError(dir.string() + ": cannot create the output folder (" + error.message() + ")");
    ev::WriteMapServer(simulated.floor_plan, dir / "floor_plan.yaml");
    const ev::RobotLog robot = ev::RobotLogOf(sequence);
    ev::WriteRobotLog(robot, dir / "sequence.log", ev::SequenceWriteFormat::kCarmen);
    if (ev::RawlogSupported()) ev::WriteRobotLog(robot, dir / "sequence.rawlog", ev::SequenceWriteFormat::kRawlog);
    ev::WriteTum(*sequence.reference, dir / "ground_truth.tum");
    ev::WriteTum(sequence.odometry, dir / "odometry.tum");
    nlohmann::json specification = simulated.specification;
    specification["scans_written"] = count;
    ev::WriteOutputFile(dir / "simulation.json", [&](std::ostream& out) { out << specification.dump(2) << "\n"; });
    streams.out << "wrote " << count << " scans to " << dir.string()
                << (ev::RawlogSupported() ? "" : " (no rawlog: MRPT support not built)") << "\n";
  });
}

/// The file and relations of a relations-clock argument: a CARMEN log, or a catalog entry's log and relations.
struct ClockSources {
  std::filesystem::path log;
  std::filesystem::path relations;
};

ClockSources ResolveClockSources(const std::string& source, const std::string& catalog_option,
                                 const std::string& relations_option) {
  ClockSources sources{source, relations_option};
  std::error_code error;
  if (!std::filesystem::is_regular_file(source, error)) {
    const CatalogLocation location = FindCatalog(catalog_option);
    const ev::Catalog catalog = ev::ReadCatalog(location.catalog);
    const ev::CatalogEntry& entry = ev::FindCatalogEntry(catalog, source);
    const ev::CatalogVariables variables{{"SHARED", location.shared_root.string()}};
    sources.log = ev::ResolveCatalogPath(entry.corrected_log ? entry.corrected_log->path : entry.path, variables);
    if (relations_option.empty() && !entry.relations_path.empty()) {
      sources.relations = ev::ResolveCatalogPath(entry.relations_path, variables);
    }
  }
  if (sources.relations.empty())
    throw ev::InputError(source + ": --relations: no relations file given or in the catalog");
  return sources;
}

/// What a clock fit pairs relation stamps with: a corrected log's ODOM stream (one reading per raw scan), or
/// a raw log's own laser records (each scan with its odometry), whose stamps are the raw scans'.
struct ClockReadings {
  bool raw = false;
  std::vector<double> logged_stamps_s;
  /// The odometry at the readings as logged (chosen stamps), for the odometry fit.
  ev::Trajectory odometry;
  /// The scans on the same clock, with the odometry that moves relation ends onto them (the scan fit).
  ev::Sequence sequence;
  ev::Trajectory scan_odometry;
};

ClockReadings ClockReadingsOf(const ev::CarmenLog& log, const std::filesystem::path& path) {
  std::vector<const ev::CarmenLaserRecord*> scans;
  for (const ev::CarmenLaserRecord& record : log.lasers) {
    if (record.type == "FLASER") scans.push_back(&record);
  }
  ClockReadings readings;
  ev::CarmenSequenceOptions scan_options;
  if (log.odometry.empty()) {
    // No ODOM stream: a raw log, whose laser records carry the raw scans' stamps and the odometry.
    readings.raw = true;
    scan_options.logged_pose_is_reference = false;
    for (const ev::CarmenLaserRecord* scan : scans) readings.logged_stamps_s.push_back(scan->ipc_stamp_s);
    readings.sequence = ev::CarmenLogToSequence(log, path, scan_options);
    readings.odometry = readings.sequence.odometry;
    readings.scan_odometry = readings.sequence.odometry;
    return readings;
  }
  ev::RecordedOdometry odometry = ev::RebuildRecordedOdometry(log, scans, path, {});
  readings.logged_stamps_s = std::move(odometry.logged_stamps_s);
  readings.odometry = std::move(odometry.readings);
  scan_options.odometry = ev::OdometryMode::kRecorded;
  readings.sequence = ev::CarmenLogToSequence(log, path, scan_options);
  readings.scan_odometry = readings.sequence.odometry_readings;
  return readings;
}

/// The relations whose both stamps the stamp fit maps inside the readings' span.
ev::Relations InsideTheReadings(const ev::Relations& relations, const ev::RelationsClockFit& fit,
                                const ev::Trajectory& readings) {
  ev::Relations inside;
  const double first_s = readings.StartS();
  const double last_s = readings.EndS();
  for (const ev::Relation& relation : relations) {
    const double t1 = fit.rate * relation.t1_s + fit.offset_s;
    const double t2 = fit.rate * relation.t2_s + fit.offset_s;
    if (std::min(t1, t2) >= first_s && std::max(t1, t2) <= last_s) inside.push_back(relation);
  }
  return inside;
}

void RegisterRelationsClock(CLI::App& data, const Streams& streams) {
  struct Options {
    std::string source;
    std::string catalog;
    std::string relations;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = data.add_subcommand(
      "relations-clock",
      "fit the map from a relations file's clock onto a CARMEN log's: relation stamps against the raw-scan stamps "
      "of a corrected log's ODOM stream, or of a raw log's laser records; then from its odometry and its scans "
      "(an offset and a rate each)");
  command->add_option("SOURCE", options->source, "CARMEN log (corrected or raw), or catalog name")->required();
  command->add_option("--relations", options->relations, "relations file (default: the catalog entry's)");
  command->add_option("--catalog", options->catalog, "dataset catalog (default: configs/datasets.yaml)");
  command->add_flag("--json", options->json, "print one JSON object");
  command->callback([options, streams] {
    const ClockSources sources = ResolveClockSources(options->source, options->catalog, options->relations);
    const ev::CarmenLog log = ev::ReadCarmenLog(sources.log);
    const ClockReadings readings = ClockReadingsOf(log, sources.log);
    std::vector<double> relation_stamps;
    const ev::Relations relations = ev::ReadRelations(sources.relations);
    for (const ev::Relation& relation : relations) {
      relation_stamps.push_back(relation.t1_s);
      relation_stamps.push_back(relation.t2_s);
    }
    const ev::RelationsClockFit fit = ev::FitRelationsClock(relation_stamps, readings.logged_stamps_s);
    // A log of part of a run: the searches weigh the relations that the stamp fit puts inside the readings.
    const ev::Relations inside = InsideTheReadings(relations, fit, readings.odometry);
    const ev::SearchedClockFit by_odometry = ev::FitRelationsClockByOdometry(inside, readings.odometry);
    const double odometry_middle_s = 0.5 * (by_odometry.first_half_offset_s + by_odometry.second_half_offset_s);
    const ev::SearchedClockFit by_scans =
        ev::FitRelationsClockByScans(inside, readings.sequence.scans, readings.scan_odometry, odometry_middle_s);
    nlohmann::json out = fit.ToJson();
    out["by_odometry"] = by_odometry.ToJson();
    out["by_scans"] = by_scans.ToJson();
    out["log"] = sources.log.string();
    out["relations"] = sources.relations.string();
    out["readings"] = readings.logged_stamps_s.size();
    out["readings_from"] = readings.raw ? "laser records" : "ODOM stream";
    out["relations_inside"] = inside.size();
    out["relations_in_file"] = relations.size();
    if (options->json) {
      streams.out << out.dump() << "\n";
      return;
    }
    streams.out << fmt::format(
        "from time stamps (relation stamps paired with the {} stamps):\n"
        "relations_rate: {:.12g}\nrelations_offset_s: {:.12g}\n{} of {} relation stamps paired with a reading within "
        "{:.3f} s (half the readings' median spacing), {} within 10 ms; residual rms {:.4f} s, max {:.4f} s; the rate "
        "takes up {:.4f} s of drift over the relations' span\n",
        readings.raw ? "laser records'" : "ODOM readings'", fit.rate, fit.offset_s, fit.matched, fit.stamps,
        fit.tolerance_s, fit.matched_within_10ms, fit.rms_residual_s, fit.max_abs_residual_s, fit.drift_over_span_s);
    if (inside.size() < relations.size()) {
      streams.out << fmt::format(
          "{} of the {} relations lie inside the log under this map: the fits below weigh those (the log holds part "
          "of the run)\n",
          inside.size(), relations.size());
    }
    streams.out << fmt::format(
        "from the recorded odometry (relations' rotations against the odometry's; inherits any lag of the odometry):\n"
        "relations_rate: {:.12g}\nrelations_offset_s: {:.12g}\n{} short relations turn as the odometry does within "
        "{:.4f} deg on average (the best offset more than 0.1 s away: {:.4f} deg); halves fitted at {:.4f} and {:.4f} "
        "s\n",
        by_odometry.rate, by_odometry.offset_s, by_odometry.relations, by_odometry.disagreement,
        by_odometry.next_best_disagreement, by_odometry.first_half_offset_s, by_odometry.second_half_offset_s);
    streams.out << fmt::format(
        "from the laser scans (each relation laid over the scans at its stamps, searched within 0.5 s of the "
        "odometry's map):\nrelations_rate: {:.12g}\nrelations_offset_s: {:.12g}\n{} relations lay their scans over "
        "each other within {:.3f} cm rms (the best offset more than 0.1 s away: {:.3f} cm); halves fitted at {:.4f} "
        "and {:.4f} s\n",
        by_scans.rate, by_scans.offset_s, by_scans.relations, by_scans.disagreement, by_scans.next_best_disagreement,
        by_scans.first_half_offset_s, by_scans.second_half_offset_s);
  });
}

}  // namespace

void RegisterDataCommands(CLI::App& app, const Streams& streams) {
  CLI::App* data = app.add_subcommand("data", "inspect, convert, map and simulate sequences");
  data->require_subcommand(1);
  RegisterInfo(*data, streams);
  RegisterConvert(*data, streams);
  RegisterMap(*data, streams);
  RegisterSimulate(*data, streams);
  RegisterRelationsClock(*data, streams);
}

}  // namespace slamsweep::cli
