#include "orchestrator/run/run_json.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

// The example of orchestrator/DESIGN.md "run.json", written out by hand.
const json kDesignExample = json::parse(R"({
  "run_id": "icp-slam-mrpt-telecom-clean-i0-1a2b3c4d",
  "sweep": "quickstart",
  "algorithm": {"name": "icp-slam", "adapter": "mrpt-icp-slam",
                "parameters": {"ICP.maxIterations": 80},
                "timeout_s": 300, "memory_limit_mb": 4096, "command": null},
  "sequence": {"name": "mrpt-telecom", "format": "rawlog", "path": "/usr/share/x.rawlog", "ground_truth": "none",
               "relations": "", "relations_offset_s": 0, "max_range_m": null, "stamp_policy": "auto",
               "max_scans": null, "simulation": null, "citation": "c", "licence": "l", "download": "d"},
  "noise": {"name": "clean", "odometry": null, "range": null},
  "iteration": 0,
  "seed": 123456789,
  "evaluation": {"align": "se2", "rpe_delta_m": 1.0, "t_max_diff_s": 0.01, "stages": 24},
  "thresholds": [{"metric": "ape_trans", "statistic": "rmse", "max": 0.5}]
})");

TEST(RunSpecTest, ReadsTheDesignDocumentExample) {
  const RunSpec spec = RunSpecFromJson(kDesignExample);
  EXPECT_EQ(spec.run_id, "icp-slam-mrpt-telecom-clean-i0-1a2b3c4d");
  EXPECT_EQ(spec.sweep, "quickstart");
  EXPECT_EQ(spec.algorithm.name, "icp-slam");
  EXPECT_EQ(spec.algorithm.adapter, "mrpt-icp-slam");
  EXPECT_EQ(spec.algorithm.parameters, (json{{"ICP.maxIterations", 80}}));
  EXPECT_DOUBLE_EQ(spec.algorithm.timeout_s, 300.0);
  EXPECT_EQ(spec.algorithm.memory_limit_mb, 4096u);
  EXPECT_FALSE(spec.algorithm.command.has_value());
  EXPECT_EQ(spec.sequence.entry.name, "mrpt-telecom");
  EXPECT_EQ(spec.sequence.entry.format, "rawlog");
  EXPECT_EQ(spec.sequence.entry.ground_truth, evaluator::GroundTruthKind::kNone);
  EXPECT_FALSE(spec.sequence.entry.max_range_m.has_value());
  EXPECT_FALSE(spec.sequence.max_scans.has_value());
  EXPECT_EQ(spec.sequence.entry.citation, "c");
  EXPECT_EQ(spec.sequence.entry.licence_note, "l");
  EXPECT_EQ(spec.sequence.entry.download_hint, "d");
  EXPECT_EQ(spec.noise.name, "clean");
  EXPECT_FALSE(spec.noise.odometry.has_value());
  EXPECT_EQ(spec.iteration, 0);
  EXPECT_EQ(spec.seed, 123456789u);
  EXPECT_EQ(spec.evaluation.stages, 24u);
  ASSERT_EQ(spec.thresholds.size(), 1u);
  EXPECT_EQ(spec.thresholds[0].max, 0.5);
  EXPECT_FALSE(spec.thresholds[0].min.has_value());
}

RunSpec FullSpec() {
  RunSpec spec;
  spec.run_id = "gm-floor-noisy-i2-0badf00d";
  spec.sweep = "s";
  spec.algorithm.name = "gm";
  spec.algorithm.adapter = "command";
  spec.algorithm.parameters = {{"particles", 30}, {"mode", "fast"}, {"on", true}, {"rate", 0.25}};
  spec.algorithm.timeout_s = 12.5;
  spec.algorithm.memory_limit_mb = 512;
  CommandDeclaration command;
  command.argv = {"gfs", "-filename", "{input}", "-p", "{param:particles}"};
  command.input_format = "carmen";
  command.trajectory = DeclaredOutput{"out.log", "carmen"};
  command.map = DeclaredOutput{"map.yaml", "map_server"};
  command.stage_maps_glob = "stages/*.pgm";
  command.stage_unknown_value = 128;
  spec.algorithm.command = command;
  spec.sequence.entry.name = "floor";
  spec.sequence.entry.format = "simulated";
  spec.sequence.entry.ground_truth = evaluator::GroundTruthKind::kExact;
  spec.sequence.entry.simulation = {{"floor_plan", {{"seed", 3}}}};
  spec.sequence.entry.max_range_m = 32.75;
  spec.sequence.entry.stamp_policy = "record_order";
  spec.sequence.entry.relations_path = "/r.relations";
  spec.sequence.entry.relations_offset_s = -12.5;
  spec.sequence.max_scans = 300;
  spec.noise.name = "noisy";
  spec.noise.odometry = evaluator::OdometryNoise{0.01, 0.002, 0.03, 0.004, 0.001, 0.02};
  spec.noise.range = evaluator::RangeNoise{0.02, 0.01, 0.005};
  spec.iteration = 2;
  spec.seed = 18446744073709551615ULL;
  spec.evaluation = EvaluationOptions{"sim3", 2.0, 0.05, 8, 0.1, true, 0.9, std::nullopt};
  spec.thresholds = {Threshold{"ape_trans", "rmse", 1.0, std::nullopt}, Threshold{"corners", "value", 50.0, 2.0}};
  return spec;
}

TEST(RunSpecTest, RoundTripsEveryFieldThroughText) {
  const RunSpec spec = FullSpec();
  const RunSpec back = RunSpecFromJson(json::parse(ToJson(spec).dump()));
  EXPECT_EQ(back.run_id, spec.run_id);
  EXPECT_EQ(back.algorithm.parameters, spec.algorithm.parameters);
  EXPECT_EQ(back.algorithm.command, spec.algorithm.command);
  EXPECT_EQ(back.algorithm.memory_limit_mb, 512u);
  EXPECT_EQ(back.sequence.max_scans, 300u);
  EXPECT_EQ(back.sequence.entry.max_range_m, 32.75);
  EXPECT_EQ(back.sequence.entry.relations_offset_s, -12.5);
  EXPECT_EQ(back.sequence.entry.simulation, spec.sequence.entry.simulation);
  EXPECT_EQ(back.noise.odometry, spec.noise.odometry);
  EXPECT_EQ(back.noise.range, spec.noise.range);
  EXPECT_EQ(back.seed, 18446744073709551615ULL);
  EXPECT_EQ(back.evaluation.align, "sim3");
  EXPECT_EQ(back.evaluation.map_resolution_m, 0.1);
  EXPECT_EQ(back.evaluation.min_coverage, 0.9);
  ASSERT_EQ(back.thresholds.size(), 2u);
  EXPECT_EQ(back.thresholds[1].min, 2.0);
  // And nothing is lost on the way: writing it again gives the same document.
  EXPECT_EQ(ToJson(back), ToJson(spec));
}

TEST(RunSpecTest, TheSandboxFieldsRoundTripAndLeaveTheRunIdAloneUnlessDeclared) {
  RunSpec spec = FullSpec();
  const json identity = RunIdentity(spec);
  EXPECT_FALSE(ToJson(spec)["algorithm"]["command"].contains("read_only"));
  spec.algorithm.disk_limit_mb = 64;
  spec.algorithm.process_limit = 16;
  spec.algorithm.network = true;
  spec.allow_unisolated = true;
  // Resources, like the timeout: the same experiment.
  EXPECT_EQ(RunIdentity(spec), identity);
  spec.algorithm.command->read_only = {"/opt/slam/config"};
  EXPECT_NE(RunIdentity(spec), identity);
  const RunSpec back = RunSpecFromJson(json::parse(ToJson(spec).dump()));
  EXPECT_EQ(back.algorithm.disk_limit_mb, 64u);
  EXPECT_EQ(back.algorithm.process_limit, 16u);
  EXPECT_TRUE(back.algorithm.network);
  EXPECT_TRUE(back.allow_unisolated);
  EXPECT_EQ(back.algorithm.command->read_only, (std::vector<std::string>{"/opt/slam/config"}));
  // An older run.json without them reads with the defaults.
  json old = ToJson(FullSpec());
  old["algorithm"].erase("disk_limit_mb");
  old["algorithm"].erase("process_limit");
  old["algorithm"].erase("network");
  old.erase("allow_unisolated");
  const RunSpec defaults = RunSpecFromJson(old);
  EXPECT_EQ(defaults.algorithm.disk_limit_mb, kDefaultDiskLimitMb);
  EXPECT_EQ(defaults.algorithm.process_limit, kDefaultProcessLimit);
  EXPECT_FALSE(defaults.algorithm.network);
  EXPECT_FALSE(defaults.allow_unisolated);
  json relative = ToJson(spec);
  relative["algorithm"]["command"]["read_only"] = {"config"};
  EXPECT_THROW(RunSpecFromJson(relative), evaluator::InputError);
}

TEST(RunSpecTest, SegmentLengthsRoundTripAsAutoOrAList) {
  RunSpec spec = FullSpec();
  EXPECT_EQ(ToJson(spec)["evaluation"]["rpe_segments_m"], "auto");
  EXPECT_FALSE(RunSpecFromJson(ToJson(spec)).evaluation.rpe_segments_m);
  spec.evaluation.rpe_segments_m = std::vector<double>{5.0, 12.5};
  const json written = ToJson(spec);
  EXPECT_EQ(written["evaluation"]["rpe_segments_m"], json::array({5.0, 12.5}));
  EXPECT_EQ(RunSpecFromJson(written).evaluation.rpe_segments_m, spec.evaluation.rpe_segments_m);
  json bad = written;
  bad["evaluation"]["rpe_segments_m"] = json::array({5.0, -1.0});
  EXPECT_THROW(RunSpecFromJson(bad), evaluator::InputError);
}

// A run scored under other evaluation options is not the same result: a rerun redoes it
// (sweep/RecordedRunIsReusable). A run.json from before a field existed matches its default.
TEST(RunSpecTest, SameEvaluationComparesTheScoringOptions) {
  const RunSpec spec = FullSpec();
  const json recorded = ToJson(spec)["evaluation"];
  EXPECT_TRUE(SameEvaluation(recorded, spec.evaluation));
  EvaluationOptions other = spec.evaluation;
  other.rpe_segments_m = std::vector<double>{10.0};
  EXPECT_FALSE(SameEvaluation(recorded, other));
  json older = recorded;
  older.erase("rpe_segments_m");
  EXPECT_TRUE(SameEvaluation(older, spec.evaluation));
  EXPECT_FALSE(SameEvaluation(older, other));
  EXPECT_FALSE(SameEvaluation(json("garbage"), spec.evaluation));
}

TEST(RunSpecTest, WritesTheDesignDocumentFieldNames) {
  const json out = ToJson(FullSpec());
  for (const char* key :
       {"run_id", "sweep", "algorithm", "sequence", "noise", "iteration", "seed", "evaluation", "thresholds"}) {
    EXPECT_TRUE(out.contains(key)) << key;
  }
  for (const char* key : {"name", "adapter", "parameters", "timeout_s", "memory_limit_mb", "command"}) {
    EXPECT_TRUE(out["algorithm"].contains(key)) << key;
  }
  for (const char* key : {"name", "format", "path", "ground_truth", "relations", "relations_offset_s", "max_range_m",
                          "stamp_policy", "max_scans", "simulation", "citation", "licence", "download"}) {
    EXPECT_TRUE(out["sequence"].contains(key)) << key;
  }
  EXPECT_EQ(out["sequence"]["ground_truth"], "exact");
  EXPECT_EQ(out["algorithm"]["command"]["argv"][4], "{param:particles}");
}

std::string ErrorOf(const json& document) {
  try {
    RunSpecFromJson(document);
  } catch (const evaluator::InputError& error) {
    return error.what();
  }
  return "";
}

TEST(RunSpecTest, RejectsUnknownAndMistypedFieldsByPath) {
  json typo = kDesignExample;
  typo["algorithm"]["timeout"] = 5;
  EXPECT_THAT(ErrorOf(typo), HasSubstr("run.json: algorithm.timeout: unknown option"));

  json top = kDesignExample;
  top["iterations"] = 1;
  EXPECT_THAT(ErrorOf(top), HasSubstr("run.json: iterations: unknown option"));

  json mistyped = kDesignExample;
  mistyped["algorithm"]["timeout_s"] = "soon";
  EXPECT_THAT(ErrorOf(mistyped), HasSubstr("run.json: algorithm.timeout_s: expected a number, got \"soon\""));

  json seed = kDesignExample;
  seed["seed"] = -1;
  EXPECT_THAT(ErrorOf(seed), HasSubstr("run.json: seed: expected an integer >= 0"));

  json no_seed = kDesignExample;
  no_seed.erase("seed");
  EXPECT_THAT(ErrorOf(no_seed), HasSubstr("run.json: seed: missing"));

  json format = kDesignExample;
  format["sequence"]["format"] = "bag";
  EXPECT_THAT(ErrorOf(format),
              HasSubstr("run.json: sequence.format: expected carmen, rawlog, rosbag, rosbag2 or simulated"));

  json noise = kDesignExample;
  noise["noise"]["odometry"] = {{"alpha1", -1.0}};
  EXPECT_THAT(ErrorOf(noise), HasSubstr("run.json: noise.odometry.alpha1"));

  json parameter = kDesignExample;
  parameter["algorithm"]["parameters"]["x"] = json::array({1, 2});
  EXPECT_THAT(ErrorOf(parameter), HasSubstr("run.json: algorithm.parameters.x: expected a number, string or bool"));

  json argv = kDesignExample;
  argv["algorithm"]["command"] = {{"argv", json::array({"prog", 3})}};
  EXPECT_THAT(ErrorOf(argv), HasSubstr("run.json: algorithm.command.argv[1]: expected a string"));

  json scans = kDesignExample;
  scans["sequence"]["max_scans"] = 0;
  EXPECT_THAT(ErrorOf(scans), HasSubstr("run.json: sequence.max_scans: expected an integer >= 1"));

  json threshold = kDesignExample;
  threshold["thresholds"][0].erase("max");
  EXPECT_THAT(ErrorOf(threshold), HasSubstr("run.json: thresholds[0]: expected a limit"));

  EXPECT_THAT(ErrorOf(json::array()), HasSubstr("run.json: (top level): expected an object"));
  EXPECT_THAT(ErrorOf(json{{"run_id", "x"}}), HasSubstr("run.json: algorithm: missing"));
}

TEST(RunSpecTest, IdentityHoldsWhatDecidesTheResultAndNothingElse) {
  const RunSpec spec = FullSpec();
  const json identity = RunIdentity(spec);
  EXPECT_EQ(identity["algorithm"]["name"], "gm");
  EXPECT_EQ(identity["iteration"], 2);
  EXPECT_EQ(identity["seed"], spec.seed);
  // Limits and scoring options do not change what the program computes.
  EXPECT_FALSE(identity["algorithm"].contains("timeout_s"));
  EXPECT_FALSE(identity.contains("evaluation"));
  EXPECT_FALSE(identity.contains("run_id"));

  RunSpec other = spec;
  other.sequence.entry.citation = "another citation";
  other.algorithm.timeout_s = 999;
  other.run_id = "renamed";
  EXPECT_EQ(RunIdentity(other), identity);
  // The reference map is scoring, not input: naming one changes no run id.
  other.sequence.entry.reference_map_path = "/data/intel-reference.yaml";
  EXPECT_EQ(RunIdentity(other), identity);
  other.sequence.max_scans = 301;
  EXPECT_NE(RunIdentity(other), identity);
}

TEST(RunSpecTest, AReferenceMapIsWrittenOnlyWhenSet) {
  RunSpec spec = FullSpec();
  EXPECT_FALSE(ToJson(spec)["sequence"].contains("reference_map"));  // run.json of every earlier sweep stays the same
  spec.sequence.entry.reference_map_path = "/data/intel-reference.yaml";
  const json out = ToJson(spec);
  EXPECT_EQ(out["sequence"]["reference_map"], "/data/intel-reference.yaml");
  EXPECT_EQ(RunSpecFromJson(out).sequence.entry.reference_map_path, "/data/intel-reference.yaml");
}

}  // namespace
}  // namespace slamsweep::orchestrator

namespace slamsweep::orchestrator {
namespace {

TEST(RunSpecTest, ABagsTopicsFramesAndMeasuredKindRoundTripAndAreWrittenOnlyWhenSet) {
  RunSpec spec = FullSpec();
  const json before = ToJson(spec);
  for (const char* key : {"scan_topic", "odometry_topic", "odom_frame", "base_frame", "laser_frame", "reference_topic",
                          "reference_frame"}) {
    EXPECT_FALSE(before["sequence"].contains(key)) << key;  // run ids of entries without them stay the same
  }
  spec.sequence.entry.format = "rosbag2";
  spec.sequence.entry.path = "bags/run1";
  spec.sequence.entry.simulation = nullptr;
  spec.sequence.entry.ground_truth = evaluator::GroundTruthKind::kMeasured;
  spec.sequence.entry.bag.scan_topic = "/scan_front";
  spec.sequence.entry.bag.base_frame = "base_footprint";
  spec.sequence.entry.bag.reference_topic = "/ground_truth";
  const json out = ToJson(spec);
  EXPECT_EQ(out["sequence"]["ground_truth"], "measured");
  EXPECT_EQ(out["sequence"]["scan_topic"], "/scan_front");
  EXPECT_EQ(out["sequence"]["reference_topic"], "/ground_truth");
  EXPECT_FALSE(out["sequence"].contains("laser_frame"));
  const RunSpec back = RunSpecFromJson(out);
  EXPECT_EQ(back.sequence.entry.format, "rosbag2");
  EXPECT_EQ(back.sequence.entry.ground_truth, evaluator::GroundTruthKind::kMeasured);
  EXPECT_EQ(back.sequence.entry.bag, spec.sequence.entry.bag);
}

TEST(RunSpecTest, TrajectoryThresholdsApplyToAMeasuredReference) {
  evaluator::CatalogEntry entry;
  entry.format = "rosbag2";
  const Threshold ape{"ape_trans", "rmse", 0.5, std::nullopt};
  const Threshold map{"map_iou_occupied", "value", std::nullopt, 0.5};
  entry.ground_truth = evaluator::GroundTruthKind::kNone;
  EXPECT_FALSE(ThresholdApplies(ape, entry));
  EXPECT_FALSE(ThresholdApplies(map, entry));
  entry.ground_truth = evaluator::GroundTruthKind::kMeasured;
  EXPECT_TRUE(ThresholdApplies(ape, entry));
  EXPECT_TRUE(ThresholdApplies(map, entry));
}

}  // namespace
}  // namespace slamsweep::orchestrator
