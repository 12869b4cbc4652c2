// RunWorker end to end with fake SLAM programs: small shell scripts declared through the command
// adapter, each showing one way a run ends. Expected values come from the inputs the test wrote
// (a trajectory shifted by a known offset, a hand-made map), never from the worker's output.

#include "orchestrator/worker/worker.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <string>
#include <thread>

#include "evaluator/formats/map/image_file.h"
#include "evaluator/formats/map/map_file.h"
#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/formats/trajectory/segment_errors_csv.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "evaluator/sequence_io/robot_log_file.h"
#include "orchestrator/adapters/run_inputs.h"
#include "orchestrator/worker/program_sandbox.h"
#include "tests/orchestrator/worker/run_spec_fixture.h"
#include "tests/support/shared_data.h"
#include "tests/support/sparse_carmen_log.h"

namespace slamsweep::orchestrator {
namespace {

namespace ev = slamsweep::evaluator;
namespace fs = std::filesystem;
using testing::ReadJson;
using testing::ReadText;
using testing::WriteScript;

constexpr double kShiftM = 0.3;
constexpr int kMapSide = 20;

/// The value of one flat metric of result.json, or NaN when it is not there.
double Metric(const nlohmann::json& result, const std::string& metric, const std::string& statistic) {
  for (const nlohmann::json& entry : result["metrics"]) {
    if (entry["metric"] == metric && entry["statistic"] == statistic) return entry["value"].get<double>();
  }
  return std::nan("");
}

class WorkerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    spec_ = testing::SimulatedRun("command", 60);
    spec_.evaluation.align = "none";
    // 60 simulated scans cover under 2 m, too little for two 1 m RPE steps; 0.2 m steps give several.
    spec_.evaluation.rpe_delta_m = 0.2;
    // The "estimate": the exact ground truth moved 0.3 m along x. Unaligned, every pose is off by
    // exactly 0.3 m (APE) while every relative motion is exact (RPE 0).
    const RunInputs inputs = PrepareRunInputs(spec_);
    ASSERT_TRUE(inputs.truth.reference);
    ev::Trajectory shifted = *inputs.truth.reference;
    for (ev::Pose& pose : shifted.mutable_poses()) pose.position.x() += kShiftM;
    ev::WriteTum(shifted, tools_ / "estimate.tum");
    // A 20 x 20 room: free inside, one ring of occupied wall cells (76 of 400).
    ev::OccupancyGrid room(kMapSide, kMapSide, 0.1, {}, 0.0f);
    for (int i = 0; i < kMapSide; ++i) {
      room.at(0, i) = room.at(kMapSide - 1, i) = room.at(i, 0) = room.at(i, kMapSide - 1) = 1.0f;
    }
    ev::WriteMapServer(room, tools_ / "room.yaml");
    run_dir_ = dir_ / "runs" / "r1";
  }

  /// Declares `script` (body of a /bin/sh script run in the tools folder, $1 = the raw/ folder) as
  /// the run's program; the tools folder with its canned outputs is what it declares it reads.
  void UseProgram(const std::string& body) {
    CommandDeclaration declaration;
    declaration.argv = {
        WriteScript(tools_ / "program.sh", "cd '" + tools_.path().string() + "' || exit 9\n" + body).string(),
        "{output_dir}"};
    declaration.read_only = {tools_.path().string()};
    declaration.trajectory = DeclaredOutput{"trajectory.tum", "tum"};
    declaration.map = DeclaredOutput{"map.yaml", "map_server"};
    spec_.algorithm.command = declaration;
  }

  nlohmann::json Run() {
    testing::WriteRunJson(run_dir_, spec_);
    EXPECT_EQ(RunWorker(run_dir_), kWorkerWroteResult);
    return ReadJson(run_dir_ / "result.json");
  }

  static constexpr const char* kWriteOutputs =
      "cp estimate.tum \"$1/trajectory.tum\" && cp room.yaml room.pgm \"$1/\" && mv \"$1/room.yaml\" \"$1/map.yaml\"";

  /// The sweep's output folder (run_dir_ = dir_/runs/r1) and, apart from it, the program's own folder.
  slamsweep::testing::TempDir dir_;
  slamsweep::testing::TempDir tools_;
  fs::path run_dir_;
  RunSpec spec_;
};

TEST_F(WorkerTest, ATrajectoryThatStopsHalfWayFailsTheRunWithItsCoverage) {
  // The first 30 lines of the 60-pose TUM file (a header line, then 29 poses): 28 of the reference's
  // 59 scan intervals, 0.1 s each.
  UseProgram(
      "head -n 30 estimate.tum > \"$1/trajectory.tum\" && cp room.yaml room.pgm \"$1/\" && "
      "mv \"$1/room.yaml\" \"$1/map.yaml\"");
  const nlohmann::json result = Run();
  EXPECT_EQ(result["status"], "failed") << result.dump(2);
  EXPECT_EQ(result["failure_kind"], "incomplete_trajectory");
  EXPECT_NE(result["reason"].get<std::string>().find("covers 47.5 % of the reference's time span"), std::string::npos)
      << result["reason"];
  EXPECT_NE(result["reason"].get<std::string>().find("below evaluation.min_coverage 95 %"), std::string::npos);

  // The same run with the check lowered to 40 % is ok, and records its coverage.
  spec_.evaluation.min_coverage = 0.4;
  const nlohmann::json lowered = Run();
  EXPECT_EQ(lowered["status"], "ok") << lowered.dump(2);
  EXPECT_NEAR(lowered["metric_details"]["coverage"]["fraction"].get<double>(), 28.0 / 59.0, 1e-9);
}

TEST_F(WorkerTest, AProgramThatWritesItsOutputsGivesAnOkRunWithMetrics) {
  UseProgram(kWriteOutputs);
  const nlohmann::json result = Run();
  EXPECT_EQ(result["status"], "ok") << result.dump(2);
  EXPECT_TRUE(result["failure_kind"].is_null());
  EXPECT_EQ(result["exit_code"], 0);
  EXPECT_EQ(result["run_id"], "test-run");
  EXPECT_NEAR(Metric(result, "ape_trans", "rmse"), kShiftM, 1e-9);
  EXPECT_NEAR(Metric(result, "ape_trans", "max"), kShiftM, 1e-9);
  EXPECT_NEAR(Metric(result, "ape_rot", "rmse"), 0.0, 1e-6);
  EXPECT_NEAR(Metric(result, "rpe_trans", "rmse"), 0.0, 1e-9) << result["warnings"];
  // The room: 76 wall cells of 400, nothing unknown.
  EXPECT_NEAR(Metric(result, "occupied_to_all", "value"), 76.0 / 400.0, 1e-12);
  EXPECT_NEAR(Metric(result, "occupied_to_free_unknown", "value"), 76.0 / 324.0, 1e-12);
  EXPECT_EQ(Metric(result, "unknown_to_all", "value"), 0.0);
  EXPECT_FALSE(std::isnan(Metric(result, "corners", "value")));
  EXPECT_FALSE(std::isnan(Metric(result, "enclosed_areas", "value")));
  EXPECT_EQ(result["metric_details"]["ape_trans"]["specification"]["alignment"], "none");
  EXPECT_TRUE(result["metric_details"].contains("paper_map"));

  const nlohmann::json& outputs = result["outputs"];
  EXPECT_EQ(outputs["map"], "map.yaml");
  EXPECT_EQ(outputs["trajectory"], "trajectory.tum");
  EXPECT_EQ(outputs["reference"], "reference.tum");
  EXPECT_EQ(outputs["log"], "log.txt");
  // The map's borders are traced from map.yaml when wanted (report, `slamsweep vectorize`), not stored.
  EXPECT_FALSE(outputs.contains("vector_map"));
  EXPECT_FALSE(fs::exists(run_dir_ / "map.geojson"));
  // Every stage in one animated PNG; no separate stage images, no uncompressed map.
  EXPECT_EQ(outputs["stage_count"], spec_.evaluation.stages);
  EXPECT_EQ(outputs["stage_animation"], "stages.png");
  EXPECT_TRUE(outputs["stages"].empty());
  EXPECT_FALSE(fs::exists(run_dir_ / "stages"));
  EXPECT_FALSE(fs::exists(run_dir_ / "map.pgm"));
  for (const char* file : {"map.yaml", "map.png", "stages.png", "trajectory.tum", "reference.tum", "command.txt"}) {
    EXPECT_TRUE(fs::exists(run_dir_ / file)) << file;
  }
  EXPECT_EQ(ReadText(run_dir_ / "command.txt"),
            (tools_ / "program.sh").string() + "\n" + (run_dir_ / "raw").string() + "\n");
  EXPECT_EQ(ev::ReadMapServer(run_dir_ / "map.yaml").width, kMapSide);
  EXPECT_FALSE(fs::exists(run_dir_ / "result.json.tmp"));

  // Every segment of the segment RPE, beside its statistics (the report's boxplots pool them).
  ASSERT_EQ(outputs["rpe_segments"], "rpe_segments.csv");
  const std::vector<ev::SegmentErrorRecord> segments = ev::ReadSegmentErrorsCsv(run_dir_ / "rpe_segments.csv");
  std::size_t listed = 0;
  for (const nlohmann::json& length : result["metric_details"]["segment_rpe"]["lengths"]) {
    listed += length["n"].get<std::size_t>();
  }
  EXPECT_GT(segments.size(), 0u);
  EXPECT_EQ(segments.size(), listed);
  for (const ev::SegmentErrorRecord& segment : segments) EXPECT_NEAR(segment.translation_m, 0.0, 1e-9);  // a shift only
}

TEST_F(WorkerTest, WithoutADeclaredMapTheMapIsRenderedAndStageMapsComeFromTheGlob) {
  UseProgram(
      "cp estimate.tum \"$1/trajectory.tum\" && mkdir \"$1/stages\" && cp room.pgm \"$1/stages/b.pgm\" && "
      "cp room.pgm \"$1/stages/a.pgm\" && cp room.pgm \"$1/stages/a.txt\"");
  spec_.algorithm.command->map.reset();
  spec_.algorithm.command->stage_maps_glob = "stages/*.pgm";
  const nlohmann::json result = Run();
  EXPECT_EQ(result["status"], "ok") << result.dump(2);
  EXPECT_NE(result["warnings"].dump().find("map rendered from the trajectory"), std::string::npos);
  // Two files match, in name order; the room's walls (0) stay occupied and its floor (254) free.
  ASSERT_EQ(result["outputs"]["stage_count"], 2u);
  // The animation's first frame is a whole image (what a reader without APNG support shows): a.pgm.
  const cv::Mat stage = ev::ReadGreyImageFile(run_dir_ / result["outputs"]["stage_animation"].get<std::string>());
  ASSERT_EQ(stage.rows, kMapSide);
  EXPECT_EQ(stage.at<std::uint8_t>(0, 0), 0);
  EXPECT_EQ(stage.at<std::uint8_t>(kMapSide / 2, kMapSide / 2), 254);
  EXPECT_FALSE(std::isnan(Metric(result, "ape_trans", "rmse")));
  // The rendered map is at the evaluation's resolution, not the room's 0.1 m.
  EXPECT_DOUBLE_EQ(ev::ReadMapServer(run_dir_ / "map.yaml").resolution_m, spec_.evaluation.map_resolution_m);
}

TEST_F(WorkerTest, ASegfaultIsASignalFailure) {
  UseProgram("kill -SEGV $$");
  const nlohmann::json result = Run();
  EXPECT_EQ(result["status"], "failed");
  EXPECT_EQ(result["failure_kind"], "signal");
  EXPECT_EQ(result["signal"], SIGSEGV);
  EXPECT_NE(result["reason"].get<std::string>().find("SIGSEGV"), std::string::npos) << result["reason"];
  EXPECT_TRUE(result["metrics"].empty());
}

TEST_F(WorkerTest, AHangingProgramTimesOut) {
  spec_.algorithm.timeout_s = 1;
  UseProgram("exec sleep 30");
  const auto start = std::chrono::steady_clock::now();
  const nlohmann::json result = Run();
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(15));
  EXPECT_EQ(result["failure_kind"], "timeout");
  EXPECT_NE(result["reason"].get<std::string>().find("timed out"), std::string::npos) << result["reason"];
}

TEST_F(WorkerTest, ANonZeroExitCodeFails) {
  UseProgram("echo 'bad things' >&2; exit 3");
  const nlohmann::json result = Run();
  EXPECT_EQ(result["failure_kind"], "exit_code");
  EXPECT_EQ(result["exit_code"], 3);
  EXPECT_EQ(result["reason"], "exit code 3");
  EXPECT_EQ(ReadText(run_dir_ / "log.txt"), "bad things\n");
}

TEST_F(WorkerTest, AMissingMapIsMissingOutputNamingTheFile) {
  UseProgram("cp estimate.tum \"$1/trajectory.tum\"");
  const nlohmann::json result = Run();
  EXPECT_EQ(result["failure_kind"], "missing_output");
  EXPECT_EQ(result["reason"], "no map: raw/map.yaml missing");
}

TEST_F(WorkerTest, AGarbageMapImageIsCorruptOutputNamingTheFile) {
  slamsweep::testing::WriteFile(tools_ / "bad.yaml",
                                "image: map.png\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
                                "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  UseProgram(
      "cp estimate.tum \"$1/trajectory.tum\" && cp bad.yaml \"$1/map.yaml\" && "
      "head -c 3000 /dev/urandom > \"$1/map.png\"");
  const nlohmann::json result = Run();
  EXPECT_EQ(result["failure_kind"], "corrupt_output") << result.dump(2);
  const std::string reason = result["reason"];
  EXPECT_TRUE(reason.starts_with("corrupt map: ")) << reason;
  EXPECT_NE(reason.find("map.png"), std::string::npos) << reason;
}

TEST_F(WorkerTest, AFloodOfOutputIsCappedAndTheRunStillCounts) {
  UseProgram("yes | head -c 100000000\n" + std::string(kWriteOutputs));
  const nlohmann::json result = Run();
  EXPECT_EQ(result["status"], "ok") << result.dump(2);
  EXPECT_LE(fs::file_size(run_dir_ / "log.txt"), (8u << 20) + 1024u);
  bool noted = false;
  for (const nlohmann::json& warning : result["warnings"]) {
    noted = noted || warning.get<std::string>().find("log.txt truncated") != std::string::npos;
  }
  EXPECT_TRUE(noted) << result["warnings"];
}

TEST_F(WorkerTest, AProgramThatCannotStartIsAnInputError) {
  CommandDeclaration declaration;
  declaration.argv = {(dir_ / "no-such-program").string()};
  declaration.trajectory = DeclaredOutput{"t.tum", "tum"};
  spec_.algorithm.command = declaration;
  const nlohmann::json result = Run();
  EXPECT_EQ(result["failure_kind"], "input_error");
  EXPECT_NE(result["reason"].get<std::string>().find("no-such-program"), std::string::npos) << result["reason"];
}

TEST_F(WorkerTest, ABadDeclarationIsAnInputErrorInTheResult) {
  spec_.algorithm.adapter = "gfs_nogui";
  const nlohmann::json result = Run();
  EXPECT_EQ(result["failure_kind"], "input_error");
  EXPECT_NE(result["reason"].get<std::string>().find("algorithm.adapter"), std::string::npos);
}

TEST_F(WorkerTest, AnUnreadableRunJsonReturnsTwoAndWritesNothing) {
  fs::create_directories(run_dir_);
  slamsweep::testing::WriteFile(run_dir_ / "run.json", "{ not json");
  EXPECT_EQ(RunWorker(run_dir_), kWorkerBadRunJson);
  EXPECT_FALSE(fs::exists(run_dir_ / "result.json"));

  nlohmann::json json = ToJson(spec_);
  json["algorithm"]["timeout_s"] = "soon";
  slamsweep::testing::WriteFile(run_dir_ / "run.json", json.dump());
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(RunWorker(run_dir_), kWorkerBadRunJson);
  const std::string message = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(message.find("run.json"), std::string::npos) << message;
  EXPECT_NE(message.find("algorithm.timeout_s"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(run_dir_ / "result.json"));
  EXPECT_EQ(RunWorker(dir_ / "no-such-run"), kWorkerBadRunJson);
}

TEST_F(WorkerTest, LeftoversOfAnEarlierAttemptAreRemoved) {
  UseProgram("cp estimate.tum \"$1/trajectory.tum\"");  // writes no map this time
  fs::create_directories(run_dir_ / "raw");
  fs::copy_file(tools_ / "room.yaml", run_dir_ / "raw" / "map.yaml");
  fs::copy_file(tools_ / "room.pgm", run_dir_ / "raw" / "room.pgm");
  slamsweep::testing::WriteFile(run_dir_ / "result.json.tmp", "half");
  const nlohmann::json result = Run();
  // The stale map of the earlier attempt must not be taken for this attempt's.
  EXPECT_EQ(result["failure_kind"], "missing_output");
  EXPECT_FALSE(fs::exists(run_dir_ / "raw" / "room.pgm"));
  EXPECT_FALSE(fs::exists(run_dir_ / "result.json.tmp"));
}

TEST_F(WorkerTest, TheOdometryBaselineRunsNoProgramAndIsScored) {
  spec_.algorithm.adapter = "odometry";
  spec_.evaluation.align = "se2";
  const nlohmann::json result = Run();
  EXPECT_EQ(result["status"], "ok") << result.dump(2);
  EXPECT_TRUE(result["command"].empty());
  EXPECT_TRUE(result["exit_code"].is_null());
  // The simulator's odometry drifts a little from the truth: an error, but a small one.
  const double ape = Metric(result, "ape_trans", "rmse");
  EXPECT_GT(ape, 0.0);
  EXPECT_LT(ape, 1.0);
  EXPECT_EQ(Metric(result, "ape_trans", "n"), 60.0);
  EXPECT_EQ(result["outputs"]["stage_count"], spec_.evaluation.stages);
  EXPECT_FALSE(std::isnan(Metric(result, "corners", "value")));
}

TEST_F(WorkerTest, ResultJsonRecordsHowFarApartTheInputsScansAre) {
  spec_.algorithm.adapter = "odometry";
  spec_.sequence.entry = {};
  spec_.sequence.entry.name = "sparse";
  spec_.sequence.entry.format = "carmen";
  spec_.sequence.entry.path =
      slamsweep::testing::WriteFile(tools_ / "sparse.log", slamsweep::testing::SparseCarmenLog());
  spec_.sequence.max_scans.reset();
  // Odometry noise changes what the program is given, not how far apart the recorded scans are.
  spec_.noise.name = "noisy";
  spec_.noise.odometry = ev::OdometryNoise{};
  spec_.noise.odometry->alpha1 = 0.05;
  spec_.noise.odometry->alpha3 = 0.05;
  const nlohmann::json result = Run();
  EXPECT_EQ(result["status"], "ok") << result.dump(2);
  const nlohmann::json& spacing = result["sequence"]["scan_spacing"];
  ASSERT_TRUE(spacing.is_object()) << result.dump(2);
  EXPECT_EQ(spacing["steps"], 4);
  EXPECT_NEAR(spacing["gap_s"]["median"].get<double>(), slamsweep::testing::kSparseLogMedianGapS, 1e-9);
  EXPECT_NEAR(spacing["gap_s"]["p95"].get<double>(), slamsweep::testing::kSparseLogP95GapS, 1e-9);
  EXPECT_NEAR(spacing["travel_m"]["median"].get<double>(), slamsweep::testing::kSparseLogMedianTravelM, 1e-9);
  EXPECT_NEAR(spacing["travel_m"]["p95"].get<double>(), slamsweep::testing::kSparseLogP95TravelM, 1e-9);
  EXPECT_NEAR(spacing["rotation_rad"]["median"].get<double>(), slamsweep::testing::kSparseLogMedianRotationRad, 1e-9);
  EXPECT_NEAR(spacing["rotation_rad"]["p95"].get<double>(), slamsweep::testing::kSparseLogP95RotationRad, 1e-9);
  EXPECT_EQ(spacing["too_sparse_for_scan_matching"], true);

  // The first three scans, as the program gets them: gaps 1 and 2 s (median 1.5, p95 1 + 0.95 = 1.95), travel 5
  // and 12 m (median 8.5).
  spec_.sequence.max_scans = 3;
  const nlohmann::json cut = Run();
  const nlohmann::json& cut_spacing = cut["sequence"]["scan_spacing"];
  EXPECT_EQ(cut_spacing["steps"], 2) << cut.dump(2);
  EXPECT_NEAR(cut_spacing["gap_s"]["p95"].get<double>(), 1.95, 1e-9);
  EXPECT_NEAR(cut_spacing["travel_m"]["median"].get<double>(), 8.5, 1e-9);
}

TEST_F(WorkerTest, EveryRunWithAReferenceIsScoredAgainstTheReferenceMap) {
  spec_.algorithm.adapter = "odometry";
  spec_.evaluation.align = "se2";
  const nlohmann::json clean = Run();
  ASSERT_EQ(clean["status"], "ok") << clean.dump(2);
  const double clean_chamfer = Metric(clean, "map_chamfer", "value");
  const double clean_f1 = Metric(clean, "map_f1", "value");
  // The simulator's odometry drifts a little: nearly the reference map, not exactly.
  EXPECT_LT(clean_chamfer, 0.2);
  EXPECT_GT(clean_f1, 0.7);
  EXPECT_TRUE(clean["metric_details"].contains("map_compare"));

  // Much more odometry noise: the map drifts away from the reference and every score says so.
  spec_.noise.name = "noisy";
  spec_.noise.odometry = evaluator::OdometryNoise{};
  spec_.noise.odometry->alpha1 = 0.2;
  spec_.noise.odometry->alpha3 = 0.2;
  const nlohmann::json noisy = Run();
  ASSERT_EQ(noisy["status"], "ok") << noisy.dump(2);
  EXPECT_GT(Metric(noisy, "map_chamfer", "value"), clean_chamfer);
  EXPECT_LT(Metric(noisy, "map_f1", "value"), clean_f1);
  EXPECT_LT(Metric(noisy, "map_iou_occupied", "value"), Metric(clean, "map_iou_occupied", "value"));
}

// The reference map is truth: while the program runs it must not exist anywhere the program is
// pointed at (input/, raw/, its environment), nor already be rendered into the sweep folder.
// The program records what it can see; the map it is later scored against must not be in there.
TEST_F(WorkerTest, TheReferenceMapIsOutOfTheProgramsReachUntilItHasExited) {
  UseProgram(
      "{ ls -la \"$1/../input\" \"$1\" \"$1/..\"; env; "
      "[ -e '" +
      (dir_ / "reference_maps").string() +
      "' ] && echo CACHE-EXISTS; "
      "cat \"$1\"/../input/* \"$1\"/* 2>/dev/null | cksum; } > \"$1/seen.txt\" 2>&1; " +
      std::string(kWriteOutputs));
  const nlohmann::json result = Run();
  ASSERT_EQ(result["status"], "ok") << result.dump(2);
  EXPECT_FALSE(std::isnan(Metric(result, "map_chamfer", "value"))) << result["warnings"];
  const nlohmann::json& reference_map = result["metric_details"]["map_compare"]["reference_map"];
  ASSERT_EQ(reference_map["source"], "rendered") << reference_map;
  const fs::path yaml = reference_map["file"].get<std::string>();
  fs::path pgm = yaml;
  pgm.replace_extension(".pgm");
  // Rendered after the program, outside the run folder.
  EXPECT_TRUE(fs::exists(pgm));
  EXPECT_TRUE(yaml.lexically_relative(run_dir_).string().starts_with("..")) << yaml << " is inside the run folder";
  const std::string seen = ReadText(run_dir_ / "raw" / "seen.txt");
  EXPECT_EQ(seen.find("CACHE-EXISTS"), std::string::npos) << "the reference map existed while the program ran";
  EXPECT_EQ(seen.find("reference_map"), std::string::npos) << seen;
  EXPECT_EQ(seen.find(yaml.stem().string()), std::string::npos) << seen;
  EXPECT_EQ(seen.find("reference.tum"), std::string::npos) << seen;
  // No file the program could read holds the map's bytes.
  const std::string map_bytes = ReadText(pgm);
  for (const fs::path& folder : {run_dir_ / "input", run_dir_ / "raw"}) {
    for (const auto& item : fs::recursive_directory_iterator(folder)) {
      if (item.is_regular_file()) {
        EXPECT_NE(ReadText(item.path()), map_bytes) << item.path();
      }
    }
  }
}

// A ROS 2 bag with a reference recorded in it (ground_truth measured) is truth: its folder is out of
// the program's reach like a corrected log's, and the run is scored against the bag's /ground_truth.
TEST_F(WorkerTest, ABagFolderWithAMeasuredReferenceIsOutOfTheProgramsReach) {
  const RunInputs inputs = PrepareRunInputs(spec_);
  slamsweep::testing::TempDir datasets;
  const fs::path folder = datasets / "floor_bag";
  ev::WriteRosbag2Folder(inputs.robot, inputs.truth.reference, folder, ev::Rosbag2StorageKind::kMcap);
  spec_.sequence.entry.format = "rosbag2";
  spec_.sequence.entry.path = folder.string();
  spec_.sequence.entry.simulation = nullptr;
  spec_.sequence.entry.ground_truth = ev::GroundTruthKind::kMeasured;
  spec_.sequence.entry.bag.reference_topic = "/ground_truth";
  const std::string probes = "cat '" + (folder / "metadata.yaml").string() +
                             "' >/dev/null 2>&1 && echo READ-METADATA\n" + "cat '" +
                             (folder / "floor_bag_0.mcap").string() + "' >/dev/null 2>&1 && echo READ-BAG\n" + "ls '" +
                             datasets.path().string() + "' >/dev/null 2>&1 && echo LIST-DATASETS\n";
  UseProgram("{\n" + probes + "} > \"$1/seen.txt\"\n" + kWriteOutputs);
  const nlohmann::json result = Run();
  ASSERT_EQ(result["status"], "ok") << result.dump(2);
  EXPECT_EQ(ReadText(run_dir_ / "raw" / "seen.txt"), "");
  // The estimate is the bag's reference moved 0.3 m: its APE is exactly that.
  EXPECT_NEAR(Metric(result, "ape_trans", "rmse"), kShiftM, 1e-9);
}

TEST_F(WorkerTest, TheProgramSeesWhatItDeclaresAndItsInputButNoResultsAndNoReferenceFiles) {
  // The catalog's reference map, in a dataset folder; a private folder; an earlier run's truth; a
  // file beside the program that it did not declare.
  slamsweep::testing::TempDir datasets;
  fs::copy_file(tools_ / "room.yaml", datasets / "room.yaml");
  fs::copy_file(tools_ / "room.pgm", datasets / "room.pgm");
  spec_.sequence.entry.reference_map_path = (datasets / "room.yaml").string();
  slamsweep::testing::TempDir private_dir;
  std::ofstream(private_dir / "queue.sqlite") << "other sweeps\n";
  fs::create_directories(dir_ / "runs" / "r0");
  std::ofstream(dir_ / "runs" / "r0" / "reference.tum") << "0 0 0 0 0 0 0 1\n";
  std::ofstream(dir_ / "results.sqlite") << "metrics\n";
  slamsweep::testing::TempDir elsewhere;
  std::ofstream(elsewhere / "notes.txt") << "not declared\n";

  const std::string out = dir_.path().string();
  std::string probes;
  const std::vector<std::string> hidden_files = {"\"$1/../run.json\"",
                                                 "\"$1/../command.txt\"",
                                                 "\"$1/../../r0/reference.tum\"",
                                                 "'" + out + "/runs/r0/reference.tum'",
                                                 "'" + out + "/results.sqlite'",
                                                 "'" + (datasets / "room.yaml").string() + "'",
                                                 "'" + (private_dir / "queue.sqlite").string() + "'",
                                                 "'" + (elsewhere / "notes.txt").string() + "'",
                                                 "/etc/shadow"};
  for (const std::string& file : hidden_files) {
    probes += "cat " + file + " >/dev/null 2>&1 && echo \"READ " + file + "\"\n";
  }
  UseProgram("{\n" + probes + "ls \"$1/../input\" >/dev/null && echo INPUT-OK\n} > \"$1/seen.txt\"\n" + kWriteOutputs);
  ::setenv(kPrivateDirsVariable, private_dir.path().c_str(), 1);
  const nlohmann::json result = Run();
  ::unsetenv(kPrivateDirsVariable);

  ASSERT_EQ(result["status"], "ok") << result.dump(2);
  const std::string seen = ReadText(run_dir_ / "raw" / "seen.txt");
  EXPECT_EQ(seen.find("READ"), std::string::npos) << seen;
  EXPECT_NE(seen.find("INPUT-OK"), std::string::npos) << seen;
  EXPECT_TRUE(result["flags"].empty()) << result["flags"];
  // The outputs reached the run folder, and the hidden reference map was used once the program had exited.
  EXPECT_NEAR(Metric(result, "ape_trans", "rmse"), kShiftM, 1e-9);
  EXPECT_EQ(result["metric_details"]["map_compare"]["reference_map"]["source"], "file")
      << result["metric_details"]["map_compare"];
  EXPECT_EQ(Metric(result, "map_chamfer", "value"), 0.0);
}

// The map scores count the cells of the map file the run folder keeps, so a page that recounts them
// from that file agrees with result.json. The program's room has walls at occupancy 100 and a floor at
// 22 (raw map_server values): map_saver writes 22 as free (<= 25), while on the program's own grey
// levels the floor is neither free nor occupied (0.22 > free_thresh 0.196).
TEST_F(WorkerTest, MapScoresCountTheCellsOfTheMapFileTheRunKeeps) {
  std::string pixels;
  for (int row = 0; row < kMapSide; ++row) {
    for (int col = 0; col < kMapSide; ++col) {
      const bool wall = row == 0 || col == 0 || row == kMapSide - 1 || col == kMapSide - 1;
      pixels += static_cast<char>(wall ? 100 : 22);
    }
  }
  std::ofstream(tools_ / "grey.pgm", std::ios::binary) << "P5\n20 20\n255\n" << pixels;
  std::ofstream(tools_ / "grey.yaml") << "image: grey.pgm\nresolution: 0.1\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                                         "occupied_thresh: 0.65\nfree_thresh: 0.196\nmode: raw\n";
  slamsweep::testing::TempDir datasets;
  fs::copy_file(tools_ / "room.yaml", datasets / "room.yaml");
  fs::copy_file(tools_ / "room.pgm", datasets / "room.pgm");
  spec_.sequence.entry.reference_map_path = (datasets / "room.yaml").string();
  UseProgram("cp estimate.tum \"$1/trajectory.tum\" && cp grey.pgm \"$1/\" && cp grey.yaml \"$1/map.yaml\"");
  const nlohmann::json result = Run();
  ASSERT_EQ(result["status"], "ok") << result.dump(2);
  const nlohmann::json& compare = result["metric_details"]["map_compare"];
  EXPECT_EQ(compare["scored_map"], "the run's map file") << compare;
  // Scored on the reference's 0.05 m cells, four per map cell: 76 wall cells (304), occupied in both
  // maps; all 400 cells (1,600) known in both, the 324 floor cells free in both.
  EXPECT_EQ(compare["cells"]["estimate_occupied"], 304) << compare;
  EXPECT_EQ(compare["cells"]["known_in_both"], 1600) << compare;
  EXPECT_EQ(Metric(result, "map_iou_free", "value"), 1.0);
  // The run folder's map says the same: its floor is written free.
  const ev::OccupancyGrid kept = ev::ReadMap(run_dir_ / "map.yaml");
  EXPECT_LE(kept.at(kMapSide / 2, kMapSide / 2), 0.196f);
}

TEST_F(WorkerTest, AReadOnlyFolderHoldingTheReferenceOrTheResultsFailsTheRun) {
  slamsweep::testing::TempDir datasets;
  fs::copy_file(tools_ / "room.yaml", datasets / "room.yaml");
  spec_.sequence.entry.reference_map_path = (datasets / "room.yaml").string();
  for (const fs::path& shown : {datasets.path(), datasets.path().parent_path(), dir_.path(), dir_ / "runs"}) {
    fs::create_directories(shown);
    UseProgram(kWriteOutputs);
    spec_.algorithm.command->read_only.push_back(shown.string());
    const nlohmann::json result = Run();
    EXPECT_EQ(result["failure_kind"], "input_error") << shown;
    EXPECT_NE(result["reason"].get<std::string>().find(shown.string()), std::string::npos) << result["reason"];
  }
}

TEST_F(WorkerTest, AReferenceUnderTheSystemFoldersIsCoveredWhileTheRestOfThemStaysVisible) {
  // A dataset installed by a package, with its reference beside the log.
  spec_.sequence.entry.reference_map_path = "/usr/share/slamsweep-test-dataset/map.yaml";
  fs::create_directories(run_dir_ / "raw");
  fs::create_directories(run_dir_ / "input");
  const SandboxSpec sandbox =
      ProgramSandbox(spec_, RunPaths{run_dir_}, {"/usr/share/mrpt"}, "/bin/true", FindSandboxPrograms());
  EXPECT_EQ(sandbox.hidden, (std::vector<fs::path>{"/usr/share/slamsweep-test-dataset"}));
  EXPECT_EQ(std::count(sandbox.read_only.begin(), sandbox.read_only.end(), fs::path("/usr/share/mrpt")), 0)
      << "already visible under /usr";
}

TEST_F(WorkerTest, AProgramThatLeavesALinkOutOfRawIsNotFollowed) {
  // A "trajectory" that is a link to the run's own reference, written after the program exits.
  UseProgram(
      "cp room.yaml room.pgm \"$1/\" && mv \"$1/room.yaml\" \"$1/map.yaml\" && "
      "ln -s " +
      (tools_ / "estimate.tum").string() + " \"$1/trajectory.tum\"");
  const nlohmann::json result = Run();
  EXPECT_EQ(result["failure_kind"], "missing_output") << result.dump(2);
  bool noted = false;
  for (const nlohmann::json& warning : result["warnings"]) {
    noted = noted || warning.get<std::string>().find("raw/trajectory.tum (a symbolic link)") != std::string::npos;
  }
  EXPECT_TRUE(noted) << result["warnings"];
}

TEST_F(WorkerTest, ProcessAndDiskLimitsEndTheRunNamingThem) {
  spec_.algorithm.process_limit = 8;
  // A fork bomb holds what it started and keeps trying.
  UseProgram(
      "/usr/bin/python3 -c 'import os, time\nfor i in range(12):\n  try:\n    if os.fork() == 0: "
      "time.sleep(10); os._exit(0)\n  except OSError: pass\ntime.sleep(10)'; " +
      std::string(kWriteOutputs));
  nlohmann::json result = Run();
  EXPECT_EQ(result["failure_kind"], "process_limit") << result.dump(2);
  EXPECT_NE(result["reason"].get<std::string>().find("process_limit"), std::string::npos) << result["reason"];

  spec_.algorithm.process_limit = kDefaultProcessLimit;
  spec_.algorithm.disk_limit_mb = 1;
  UseProgram("head -c 2000000 /dev/zero > \"$1/big\"; " + std::string(kWriteOutputs));
  result = Run();
  EXPECT_EQ(result["failure_kind"], "disk_limit") << result.dump(2);
  EXPECT_NE(result["reason"].get<std::string>().find("disk_limit_mb"), std::string::npos) << result["reason"];
}

TEST_F(WorkerTest, InterruptionStopsTheProgramAndLeavesNoResult) {
  UseProgram("exec sleep 30");
  testing::WriteRunJson(run_dir_, spec_);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) ::_exit(RunWorker(run_dir_));
  // Wait until the program runs (its log exists), then interrupt the worker.
  for (int i = 0; i < 200 && !fs::exists(run_dir_ / "log.txt"); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  ASSERT_EQ(::kill(child, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), kWorkerInterrupted);
  EXPECT_FALSE(fs::exists(run_dir_ / "result.json"));
  EXPECT_FALSE(fs::exists(run_dir_ / "raw"));
  EXPECT_TRUE(fs::exists(run_dir_ / "run.json"));
}

}  // namespace
}  // namespace slamsweep::orchestrator
