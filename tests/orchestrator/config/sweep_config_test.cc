#include "orchestrator/config/sweep_config.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "evaluator/core/input_error.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

/// A catalog with one CARMEN log that exists, one whose file is missing and one simulated entry.
class SweepConfigTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::create_directories(dir_.path() / "data");
    testing::WriteFile(dir_ / "data/log.carmen", "# not read while validating\n");
    testing::WriteFile(dir_ / "catalog.yaml", R"(sequences:
  - name: lab
    format: carmen
    path: ${DATA}/log.carmen
    ground_truth: corrected_poses
  - name: gone
    format: carmen
    path: ${DATA}/gone.log
    ground_truth: none
    download: http://example.org/gone.log
  - name: sim
    format: simulated
    ground_truth: exact
    simulation: {floor_plan: {seed: 3}}
)");
    context_.default_catalog = dir_ / "catalog.yaml";
    context_.variables = {{"DATA", (dir_.path() / "data").string()}};
  }

  SweepConfig Parse(const std::string& text) { return ParseSweepConfig(text, dir_ / "sweep.yaml", context_); }

  /// The message of the InputError that parsing `text` throws ("" when it does not throw).
  std::string ErrorOf(const std::string& text) {
    try {
      Parse(text);
    } catch (const evaluator::InputError& error) {
      return error.what();
    }
    return "";
  }

  std::string Located(int line, int column) const {
    return (dir_ / "sweep.yaml").string() + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
  }

  testing::TempDir dir_;
  SweepConfigContext context_;
};

constexpr const char* kMinimal = R"(name: mini
algorithms:
  - {name: odo, adapter: odometry}
sequences:
  - lab
)";

TEST_F(SweepConfigTest, MinimalFileGetsTheDocumentedDefaults) {
  const SweepConfig config = Parse(kMinimal);
  EXPECT_EQ(config.name, "mini");
  EXPECT_EQ(config.iterations, 1);
  EXPECT_EQ(config.seed, 0u);
  EXPECT_EQ(config.seed_policy, SeedPolicy::kPerIteration);
  EXPECT_EQ(config.workers, 0u);
  EXPECT_EQ(config.failure_budget, 0u);
  EXPECT_EQ(config.output_dir, dir_.path() / "out" / "mini");
  EXPECT_EQ(config.catalog, dir_.path() / "catalog.yaml");
  ASSERT_EQ(config.algorithms.size(), 1u);
  EXPECT_DOUBLE_EQ(config.algorithms[0].timeout_s, 600.0);
  EXPECT_EQ(config.algorithms[0].memory_limit_mb, 0u);
  ASSERT_EQ(config.noise.size(), 1u);
  EXPECT_EQ(config.noise[0].name, "clean");
  EXPECT_FALSE(config.noise[0].odometry.has_value());
  EXPECT_EQ(config.evaluation.align, "se2");
  ASSERT_EQ(config.sequences.size(), 1u);
  // ${DATA} is replaced: the worker gets a path it can open as is.
  EXPECT_EQ(config.sequences[0].entry.path, (dir_.path() / "data/log.carmen").string());
}

TEST_F(SweepConfigTest, ReadsEveryDocumentedField) {
  const SweepConfig config = Parse(R"(name: full-1.0
output: ../results/full
catalog: catalog.yaml
iterations: 3
seed: 18446744073709551615
seed_policy: per_run
workers: 2
failure_budget: 4
evaluation: {align: sim2, rpe_delta_m: 2.5, t_max_diff_s: 0.02, stages: 8, map_resolution_m: 0.1}
thresholds:
  - {metric: ape_trans, statistic: rmse, max: 1.0}
  - {metric: corners, statistic: value, min: 2, max: 50}
algorithms:
  - name: icp
    adapter: mrpt-icp-slam
    timeout_s: 120
    memory_limit_mb: 2048
    parameters:
      ICP.maxIterations: [40, 80]
      mode: "fast"
      quoted: ["1", 2, true]
  - name: gm
    adapter: command
    command:
      argv: [true, -filename, "{input}", -o, "{output_dir}/out.log", -p, "{param:particles}", "{seed}{iteration}{seed32}"]
      input_format: carmen
      trajectory: {path: out.log, format: carmen}
      map: {path: map.yaml, format: map_server}
      stage_maps: "stages/*.pgm"
      stage_unknown_value: 128
    parameters: {particles: [30, 60]}
sequences:
  - lab
  - {catalog: lab, name: lab-300, max_scans: 300}
  - name: floor
    format: simulated
    ground_truth: exact
    max_scans: 50
    simulation: {floor_plan: {seed: 2}}
noise:
  - name: clean
  - name: noisy
    odometry: {alpha1: 0.01, alpha3: 0.02}
    range: {sigma_m: 0.03}
exclude:
  - {algorithm: icp, sequence: lab-300, parameters: {ICP.maxIterations: 80}}
include:
  - {algorithm: gm, sequence: floor, noise: clean, parameters: {particles: 100}}
)");
  EXPECT_EQ(config.name, "full-1.0");
  EXPECT_EQ(config.output_dir, dir_.path().parent_path() / "results" / "full");
  EXPECT_EQ(config.iterations, 3);
  EXPECT_EQ(config.seed, 18446744073709551615ULL);
  EXPECT_EQ(config.seed_policy, SeedPolicy::kPerRun);
  EXPECT_EQ(config.workers, 2u);
  EXPECT_EQ(config.failure_budget, 4u);
  EXPECT_EQ(config.evaluation.align, "sim2");
  EXPECT_DOUBLE_EQ(config.evaluation.rpe_delta_m, 2.5);
  EXPECT_DOUBLE_EQ(config.evaluation.t_max_diff_s, 0.02);
  EXPECT_EQ(config.evaluation.stages, 8u);
  EXPECT_DOUBLE_EQ(config.evaluation.map_resolution_m, 0.1);
  ASSERT_EQ(config.thresholds.size(), 2u);
  EXPECT_EQ(config.thresholds[1].metric, "corners");
  EXPECT_EQ(config.thresholds[1].statistic, "value");
  EXPECT_EQ(config.thresholds[1].min, 2.0);
  EXPECT_EQ(config.thresholds[1].max, 50.0);

  const AlgorithmConfig& icp = config.algorithms[0];
  EXPECT_DOUBLE_EQ(icp.timeout_s, 120.0);
  EXPECT_EQ(icp.memory_limit_mb, 2048u);
  // Written order is kept (not sorted), and a scalar is a list of one.
  ASSERT_EQ(icp.parameters.size(), 3u);
  EXPECT_EQ(icp.parameters[0].name, "ICP.maxIterations");
  EXPECT_EQ(icp.parameters[0].values, (std::vector<nlohmann::json>{40, 80}));
  EXPECT_EQ(icp.parameters[1].name, "mode");
  EXPECT_EQ(icp.parameters[1].values, (std::vector<nlohmann::json>{"fast"}));
  // Quoted stays text; plain numbers and booleans get their types.
  EXPECT_EQ(icp.parameters[2].values, (std::vector<nlohmann::json>{"1", 2, true}));

  const AlgorithmConfig& gm = config.algorithms[1];
  ASSERT_TRUE(gm.command.has_value());
  EXPECT_EQ(gm.command->argv.size(), 8u);
  // The program is checked when the sweep is read (`true` is found in PATH) and kept as written.
  EXPECT_EQ(gm.command->argv[0], "true");
  EXPECT_EQ(gm.command->argv[2], "{input}");
  EXPECT_EQ(gm.command->input_format, "carmen");
  EXPECT_EQ(gm.command->trajectory, (DeclaredOutput{"out.log", "carmen"}));
  EXPECT_EQ(gm.command->map, (DeclaredOutput{"map.yaml", "map_server"}));
  EXPECT_EQ(gm.command->stage_maps_glob, "stages/*.pgm");
  EXPECT_EQ(gm.command->stage_unknown_value, 128);

  ASSERT_EQ(config.sequences.size(), 3u);
  EXPECT_EQ(config.sequences[1].entry.name, "lab-300");
  EXPECT_EQ(config.sequences[1].max_scans, 300u);
  EXPECT_EQ(config.sequences[1].entry.path, (dir_.path() / "data/log.carmen").string());
  EXPECT_EQ(config.sequences[2].entry.format, "simulated");
  EXPECT_EQ(config.sequences[2].max_scans, 50u);

  ASSERT_EQ(config.noise.size(), 2u);
  ASSERT_TRUE(config.noise[1].odometry.has_value());
  EXPECT_DOUBLE_EQ(config.noise[1].odometry->alpha1, 0.01);
  EXPECT_DOUBLE_EQ(config.noise[1].odometry->alpha3, 0.02);
  ASSERT_TRUE(config.noise[1].range.has_value());
  EXPECT_DOUBLE_EQ(config.noise[1].range->sigma_m, 0.03);

  ASSERT_EQ(config.exclude.size(), 1u);
  EXPECT_EQ(config.exclude[0].algorithm, "icp");
  EXPECT_EQ(config.exclude[0].sequence, "lab-300");
  EXPECT_FALSE(config.exclude[0].noise.has_value());
  EXPECT_EQ(config.exclude[0].parameters, (nlohmann::json{{"ICP.maxIterations", 80}}));
  ASSERT_EQ(config.include.size(), 1u);
  EXPECT_EQ(config.include[0].noise, "clean");
}

TEST_F(SweepConfigTest, ReadsAFileFromDisk) {
  const std::filesystem::path file = testing::WriteFile(dir_ / "disk.yaml", kMinimal);
  EXPECT_EQ(ReadSweepConfig(file, context_).name, "mini");
  EXPECT_THROW(ReadSweepConfig(dir_ / "absent.yaml", context_), evaluator::InputError);
}

// Every validation error names FILE:LINE:COLUMN (from 1) and the field path.
TEST_F(SweepConfigTest, UnknownKeysAreErrorsAtEveryLevel) {
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "iteratons: 3\n"), HasSubstr(Located(6, 1) + "iteratons: unknown key"));
  EXPECT_THAT(ErrorOf(R"(name: mini
algorithms:
  - {name: odo, adapter: odometry, timeout: 5}
sequences: [lab]
)"),
              HasSubstr(Located(3, 36) + "algorithms[0].timeout: unknown key"));
  EXPECT_THAT(ErrorOf(R"(name: mini
algorithms: [{name: odo, adapter: odometry}]
sequences: [lab]
evaluation: {align: se2, rpe_delta: 1}
)"),
              HasSubstr(Located(4, 26) + "evaluation.rpe_delta: unknown key"));
  EXPECT_THAT(ErrorOf(R"(name: mini
algorithms:
  - name: gm
    adapter: command
    command:
      argv: [true]
      trajectory: {path: a.log, format: carmen, unit: m}
sequences: [lab]
)"),
              HasSubstr(Located(7, 49) + "algorithms[0].command.trajectory.unit: unknown key"));
  EXPECT_THAT(ErrorOf(R"(name: mini
algorithms: [{name: odo, adapter: odometry}]
sequences: [lab]
noise:
  - {name: n, odometry: {alpha9: 0.1}}
)"),
              HasSubstr(Located(5, 25) + "noise[0].odometry.alpha9: unknown option"));
  EXPECT_THAT(ErrorOf(R"(name: mini
algorithms: [{name: odo, adapter: odometry}]
sequences:
  - {catalog: lab, rename: x}
)"),
              HasSubstr(Located(4, 20) + "sequences[0].rename: unknown key"));
}

// Found by fuzzing: a byte that is not UTF-8 in an option's value reached JSON, whose type_error 316 left
// the parser instead of an InputError. A sweep file must be UTF-8; the error says where it is not.
TEST_F(SweepConfigTest, TextThatIsNotUtf8IsAnErrorAtItsLineAndColumn) {
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "noise:\n  - name: n\n    odometry: {alpha1: 0.0\xFE"
                                              "5}\n"),
              HasSubstr(Located(8, 27) + "not UTF-8 text (byte 0xFE): a sweep file is UTF-8"));
  EXPECT_THAT(ErrorOf("name: x\nalgorithms:\n  - {name: \"\xC3\x28\", adapter: odometry}\n"),
              HasSubstr(Located(3, 13) + "not UTF-8 text (byte 0xC3)"));
  // yaml-cpp read a NUL and the letter after it as an escape: "\0N" became the lone byte 0x85 (also fuzzing's).
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "noise:\n  - name: " + std::string("\0N", 2) + "\n"),
              HasSubstr(Located(7, 11) + "a control character (byte 0x00)"));
}

TEST_F(SweepConfigTest, WrongTypesNameTheFieldAndWhatWasExpected) {
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "iterations: many\n"),
              HasSubstr(Located(6, 13) + "iterations: expected a whole number >= 0, got 'many'"));
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "iterations: 0\n"),
              HasSubstr(Located(6, 13) + "iterations: expected a whole number from 1 to 1000000, got '0'"));
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "seed: -1\n"),
              HasSubstr(Located(6, 7) + "seed: expected a whole number"));
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "seed_policy: random\n"),
              HasSubstr(Located(6, 14) + "seed_policy: expected per_iteration, per_run or fixed, got 'random'"));
  EXPECT_THAT(ErrorOf(R"(name: mini
algorithms:
  - {name: odo, adapter: odometry, timeout_s: soon}
sequences: [lab]
)"),
              HasSubstr(Located(3, 47) + "algorithms[0].timeout_s: expected a finite number, got 'soon'"));
  EXPECT_THAT(
      ErrorOf(R"(name: mini
algorithms:
  - {name: odo, adapter: odometry, parameters: {a: {b: 1}}}
sequences: [lab]
)"),
      HasSubstr(Located(3, 52) + "algorithms[0].parameters.a: expected a number, text or true/false, got a map"));
  EXPECT_THAT(ErrorOf("name: a/b\nalgorithms: []\n"),
              HasSubstr(Located(1, 7) + "name: expected a name of [A-Za-z0-9_.-]"));
  EXPECT_THAT(ErrorOf("name: x\nalgorithms: odo\nsequences: [lab]\n"),
              HasSubstr(Located(2, 13) + "algorithms: expected a non-empty list, got 'odo'"));
  EXPECT_THAT(ErrorOf("- just\n- a list\n"), HasSubstr(":1:1: expected a sweep"));
  EXPECT_THAT(ErrorOf("name: [unclosed\n"), HasSubstr((dir_ / "sweep.yaml").string() + ":"));
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "thresholds:\n  - {metric: ape_trns, max: 1}\n"),
              HasSubstr(Located(7, 14) + "thresholds[0].metric: expected one of ape_trans"));
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "thresholds:\n  - {metric: ape_trans}\n"),
              HasSubstr(Located(7, 5) + "thresholds[0]: expected a limit"));
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "evaluation: {align: sim4}\n"),
              HasSubstr(Located(6, 13) + "evaluation.align: expected none, origin, se2, se3, sim2 or sim3"));
}

TEST_F(SweepConfigTest, MissingRequiredFields) {
  EXPECT_THAT(ErrorOf("algorithms: [{name: odo, adapter: odometry}]\nsequences: [lab]\n"),
              HasSubstr(Located(1, 1) + "name: missing"));
  EXPECT_THAT(ErrorOf("name: x\nsequences: [lab]\n"), HasSubstr(Located(1, 1) + "algorithms: missing"));
  EXPECT_THAT(ErrorOf("name: x\nalgorithms: [{name: odo, adapter: odometry}]\n"),
              HasSubstr(Located(1, 1) + "sequences: missing"));
  EXPECT_THAT(ErrorOf("name: x\nalgorithms: [{adapter: odometry}]\nsequences: [lab]\n"),
              HasSubstr(Located(2, 14) + "algorithms[0].name: missing"));
}

TEST_F(SweepConfigTest, MissingFilesAreErrors) {
  // The catalog named by the file.
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "catalog: nowhere.yaml\n"),
              HasSubstr(Located(6, 10) + "catalog: expected a dataset catalog file, got no such file " +
                        (dir_.path() / "nowhere.yaml").string()));
  // A catalog sequence whose log is not there: the entry, the file and where to get it.
  const std::string gone =
      ErrorOf("name: x\nalgorithms: [{name: odo, adapter: odometry}]\nsequences:\n  - lab\n  - gone\n");
  EXPECT_THAT(gone, HasSubstr(Located(5, 5) + "sequences[1]: sequence 'gone': expected its file " +
                              (dir_.path() / "data/gone.log").string()));
  EXPECT_THAT(gone, HasSubstr("get it from: http://example.org/gone.log"));
  // An inline entry: relative paths are relative to the sweep file's folder.
  EXPECT_THAT(ErrorOf(R"(name: x
algorithms: [{name: odo, adapter: odometry}]
sequences:
  - {name: mine, format: carmen, path: logs/mine.log, ground_truth: none, download: ask Bob}
)"),
              HasSubstr(Located(4, 5) + "sequences[0]: sequence 'mine': expected its file " +
                        (dir_.path() / "logs/mine.log").string() + ", got no such file; get it from: ask Bob"));
  // An unknown catalog name lists the known ones.
  EXPECT_THAT(ErrorOf("name: x\nalgorithms: [{name: odo, adapter: odometry}]\nsequences: [labb]\n"),
              HasSubstr(Located(3, 13) + "sequences[0]: expected a sequence of the catalog"));
  EXPECT_THAT(ErrorOf("name: x\nalgorithms: [{name: odo, adapter: odometry}]\nsequences: [labb]\n"),
              HasSubstr("(lab, gone, sim), got 'labb'"));
}

TEST_F(SweepConfigTest, InlineEntriesAreCheckedByTheCatalogRules) {
  const SweepConfig config = Parse(R"(name: x
algorithms: [{name: odo, adapter: odometry}]
sequences:
  - {name: here, format: carmen, path: data/log.carmen, ground_truth: none}
)");
  EXPECT_EQ(config.sequences[0].entry.path, (dir_.path() / "data/log.carmen").string());
  EXPECT_THAT(ErrorOf(R"(name: x
algorithms: [{name: odo, adapter: odometry}]
sequences:
  - {name: here, format: bag, path: data/log.carmen, ground_truth: none}
)"),
              HasSubstr("sweep.yaml:4: format: expected carmen, rawlog, rosbag, rosbag2 or simulated, got 'bag'"));
}

TEST_F(SweepConfigTest, ARos2BagFolderIsCheckedWithItsMetadataAndSplitFiles) {
  const std::string sweep = R"(name: x
algorithms: [{name: odo, adapter: odometry}]
sequences:
  - {name: run1, format: rosbag2, path: bags/run1/, ground_truth: measured, reference_topic: /ground_truth}
)";
  std::filesystem::create_directories(dir_ / "bags/run1");
  EXPECT_THAT(ErrorOf(sweep), AllOf(HasSubstr(Located(4, 5) + "sequences[0]: sequence 'run1': "),
                                    HasSubstr("no metadata.yaml in the folder")));
  testing::WriteFile(dir_ / "bags/run1/metadata.yaml",
                     "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: mcap\n"
                     "  relative_file_paths: [run1_0.mcap, run1_1.mcap]\n");
  testing::WriteFile(dir_ / "bags/run1/run1_0.mcap", "");
  EXPECT_THAT(ErrorOf(sweep), HasSubstr("split file run1_1.mcap named by metadata.yaml is missing"));
  testing::WriteFile(dir_ / "bags/run1/run1_1.mcap", "");
  const SweepConfig config = Parse(sweep);
  // The folder, without its trailing '/': the sandbox hides its parent like any sequence file's folder.
  EXPECT_EQ(config.sequences[0].entry.path, (dir_.path() / "bags/run1").string());
  EXPECT_EQ(config.sequences[0].entry.ground_truth, evaluator::GroundTruthKind::kMeasured);
  EXPECT_EQ(config.sequences[0].entry.bag.reference_topic, "/ground_truth");
  // A folder is no CARMEN log.
  EXPECT_THAT(ErrorOf(R"(name: x
algorithms: [{name: odo, adapter: odometry}]
sequences:
  - {name: run1, format: carmen, path: bags/run1, ground_truth: none}
)"),
              HasSubstr("expected its file"));
}

TEST_F(SweepConfigTest, AReferenceMapIsResolvedAndMustExist) {
  testing::WriteFile(dir_ / "data/lab-map.yaml", "image: lab-map.pgm\n");
  const SweepConfig config = Parse(R"(name: x
algorithms: [{name: odo, adapter: odometry}]
sequences:
  - {name: here, format: carmen, path: data/log.carmen, ground_truth: none, reference_map: data/lab-map.yaml}
)");
  EXPECT_EQ(config.sequences[0].entry.reference_map_path, (dir_.path() / "data/lab-map.yaml").string());
  EXPECT_THAT(ErrorOf(R"(name: x
algorithms: [{name: odo, adapter: odometry}]
sequences:
  - {name: here, format: carmen, path: data/log.carmen, ground_truth: none, reference_map: data/none.yaml}
)"),
              HasSubstr(Located(4, 5) + "sequences[0]: sequence 'here': expected its reference map " +
                        (dir_.path() / "data/none.yaml").string() + ", got no such file"));
}

TEST_F(SweepConfigTest, AdaptersAndCommandDeclarationsAreChecked) {
  EXPECT_THAT(ErrorOf("name: x\nalgorithms:\n  - {name: a, adapter: gfs_nogui}\nsequences: [lab]\n"),
              HasSubstr(Located(3, 24) +
                        "algorithms[0].adapter: expected mrpt-icp-slam, mrpt-rbpf-slam, command, odometry, gmapping, "
                        "tinyslam, vinyslam, hector, cartographer, slam-toolbox, lama or lama-pf, got 'gfs_nogui'"));
  EXPECT_THAT(ErrorOf("name: x\nalgorithms:\n  - {name: a, adapter: command}\nsequences: [lab]\n"),
              HasSubstr(Located(3, 5) + "algorithms[0].command: missing"));
  EXPECT_THAT(ErrorOf(R"(name: x
algorithms:
  - name: a
    adapter: command
    command: {trajectory: {path: t.tum, format: tum}}
sequences: [lab]
)"),
              HasSubstr(Located(5, 14) + "algorithms[0].command.argv: missing"));
  EXPECT_THAT(ErrorOf(R"(name: x
algorithms:
  - name: a
    adapter: command
    command: {argv: [], trajectory: {path: t.tum, format: tum}}
sequences: [lab]
)"),
              HasSubstr(Located(5, 21) + "algorithms[0].command.argv: expected a non-empty list"));
  EXPECT_THAT(
      ErrorOf(R"(name: x
algorithms:
  - name: a
    adapter: command
    command:
      argv: [true, "{inptu}"]
      trajectory: {path: t.tum, format: tum}
sequences: [lab]
)"),
      HasSubstr(Located(6, 20) + "algorithms[0].command.argv[1]: unknown placeholder {inptu}; accepted: {input}"));
  EXPECT_THAT(ErrorOf(R"(name: x
algorithms:
  - name: a
    adapter: command
    parameters: {particles: 30}
    command:
      argv: [true, "--iterations={param:iterations}"]
      trajectory: {path: t.tum, format: tum}
sequences: [lab]
)"),
              HasSubstr(Located(7, 20) +
                        "algorithms[0].command.argv[1]: {param:iterations} names no parameter of the algorithm "
                        "(declared: particles)"));
  EXPECT_THAT(
      ErrorOf(R"(name: x
algorithms:
  - name: a
    adapter: command
    command:
      argv: [true]
      trajectory: {path: t.tum, format: g2o}
sequences: [lab]
)"),
      HasSubstr(Located(7, 41) + "algorithms[0].command.trajectory.format: expected tum, kitti, csv, mrpt or carmen"));
  EXPECT_THAT(ErrorOf(R"(name: x
algorithms:
  - name: a
    adapter: command
    command: {argv: [true]}
sequences: [lab]
)"),
              HasSubstr(Located(5, 14) + "algorithms[0].command: expected a trajectory or a map output"));
  EXPECT_THAT(ErrorOf(R"(name: x
algorithms:
  - name: a
    adapter: odometry
    command: {argv: [true]}
sequences: [lab]
)"),
              HasSubstr(Located(5, 14) + "algorithms[0].command: only the command adapter takes a command"));
}

TEST_F(SweepConfigTest, TheSandboxKeysAreCheckedAndAServerRefusesTheNetworkUnlessAllowed) {
  std::filesystem::create_directories(dir_ / "tool-config");
  const std::string head = "name: x\nsequences: [lab]\nalgorithms:\n  - name: a\n    adapter: command\n";
  const std::string command = "    command:\n      argv: [true]\n      trajectory: {path: t.tum, format: tum}\n";
  SweepConfig config = Parse(head + "    network: true\n    disk_limit_mb: 16\n    process_limit: 32\n" + command +
                             "      read_only: [tool-config, /usr/share]\n");
  const AlgorithmConfig& algorithm = config.algorithms.at(0);
  EXPECT_TRUE(algorithm.network);
  EXPECT_EQ(algorithm.disk_limit_mb, 16u);
  EXPECT_EQ(algorithm.process_limit, 32u);
  EXPECT_EQ(algorithm.command->read_only, (std::vector<std::string>{(dir_ / "tool-config").string(), "/usr/share"}));
  config = Parse(kMinimal);
  EXPECT_FALSE(config.algorithms.at(0).network);
  EXPECT_EQ(config.algorithms.at(0).disk_limit_mb, kDefaultDiskLimitMb);
  EXPECT_EQ(config.algorithms.at(0).process_limit, kDefaultProcessLimit);

  EXPECT_THAT(ErrorOf(head + command + "      read_only: [no-such-folder]\n"),
              HasSubstr(Located(9, 19) + "algorithms[0].command.read_only[0]: " + (dir_ / "no-such-folder").string() +
                        " does not exist"));
  EXPECT_THAT(ErrorOf(head + command + "      read_only: /usr\n"),
              HasSubstr(Located(9, 18) + "algorithms[0].command.read_only: expected a list of folders and files"));
  EXPECT_THAT(ErrorOf(head + "    process_limit: 1\n" + command),
              HasSubstr(Located(6, 20) + "algorithms[0].process_limit: expected"));
  EXPECT_THAT(ErrorOf(head + "    disk_limit_mb: 0\n" + command),
              HasSubstr(Located(6, 20) + "algorithms[0].disk_limit_mb: expected"));
  EXPECT_THAT(ErrorOf(head + "    network: maybe\n" + command), HasSubstr("algorithms[0].network"));

  // A submitted sweep: no network without --allow-network, no read_only outside the allowed roots.
  context_.policy.allow_network = false;
  context_.policy.allowed_roots = {dir_.path()};
  EXPECT_NO_THROW(Parse(head + command + "      read_only: [tool-config]\n"));
  EXPECT_THROW(Parse(head + "    network: true\n" + command), PolicyError);
  EXPECT_THAT(ErrorOf(head + "    network: true\n" + command), HasSubstr("--allow-network"));
  EXPECT_THROW(Parse(head + command + "      read_only: [/usr/share]\n"), PolicyError);
}

TEST_F(SweepConfigTest, DuplicateNamesAreErrors) {
  EXPECT_THAT(ErrorOf(R"(name: x
algorithms:
  - {name: a, adapter: odometry}
  - {name: a, adapter: mrpt-icp-slam}
sequences: [lab]
)"),
              HasSubstr(Located(4, 5) + "algorithms[1]: expected a unique name, got 'a' a second time"));
  EXPECT_THAT(ErrorOf("name: x\nalgorithms: [{name: a, adapter: odometry}]\nsequences: [lab, sim, lab]\n"),
              HasSubstr(Located(3, 23) + "sequences[2]: expected a unique name, got 'lab' a second time"));
  // Renaming makes a second use of one catalog entry legal.
  EXPECT_NO_THROW(
      Parse("name: x\nalgorithms: [{name: a, adapter: odometry}]\nsequences: [lab, {catalog: lab, name: l2}]\n"));
  EXPECT_THAT(
      ErrorOf("name: x\nalgorithms: [{name: a, adapter: odometry}]\nsequences: [lab]\nnoise: [{name: n}, {name: n}]\n"),
      HasSubstr(Located(4, 27) + "noise[1].name: expected a unique name, got 'n' a second time"));
  EXPECT_THAT(
      ErrorOf("name: x\nalgorithms:\n  - {name: a, adapter: odometry, parameters: {p: [1, 2, 1]}}\nsequences: [lab]\n"),
      HasSubstr(Located(3, 57) + "algorithms[0].parameters.p: value 1 is listed twice"));
}

TEST_F(SweepConfigTest, IncludeAndExcludeMustNameWhatExists) {
  const std::string head =
      "name: x\nalgorithms:\n  - {name: a, adapter: odometry, parameters: {p: [1, 2]}}\n"
      "sequences: [lab]\nnoise: [{name: clean}]\n";
  EXPECT_THAT(ErrorOf(head + "exclude:\n  - {algorithm: b}\n"),
              HasSubstr(Located(7, 17) + "exclude[0].algorithm: expected one of the sweep's names (a), got 'b'"));
  EXPECT_THAT(ErrorOf(head + "exclude:\n  - {sequence: sim}\n"),
              HasSubstr(Located(7, 16) + "exclude[0].sequence: expected one of the sweep's names (lab), got 'sim'"));
  EXPECT_THAT(ErrorOf(head + "exclude:\n  - {noise: dirty}\n"),
              HasSubstr(Located(7, 13) + "exclude[0].noise: expected one of the sweep's names (clean), got 'dirty'"));
  EXPECT_THAT(ErrorOf(head + "exclude:\n  - {algorithm: a, parameters: {q: 1}}\n"),
              HasSubstr(Located(7, 33) + "exclude[0].parameters.q: expected a parameter declared by algorithm 'a'"));
  EXPECT_THAT(ErrorOf(head + "exclude:\n  - {}\n"), HasSubstr(Located(7, 5) + "exclude[0]: expected at least one of"));
  EXPECT_THAT(ErrorOf(head + "include:\n  - {algorithm: a}\n"),
              HasSubstr(Located(7, 5) + "include[0]: expected at least an algorithm and a sequence"));
  EXPECT_THAT(ErrorOf(head + "include:\n  - {algorithm: a, sequence: lab, colour: red}\n"),
              HasSubstr(Located(7, 35) + "include[0].colour: unknown key"));
  EXPECT_NO_THROW(Parse(
      head + "exclude:\n  - {parameters: {p: 2}}\ninclude:\n  - {algorithm: a, sequence: lab, parameters: {p: 3}}\n"));
}

TEST_F(SweepConfigTest, NoiseFieldsAreValidatedByTheEvaluatorRules) {
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "noise:\n  - {name: n, odometry: {alpha1: -0.1}}\n"),
              HasSubstr(Located(7, 25) + "noise[0].odometry.alpha1"));
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "noise:\n  - {name: n, range: {sigma_m: x}}\n"),
              HasSubstr(Located(7, 22) + "noise[0].range.sigma_m: expected a number"));
}

TEST_F(SweepConfigTest, UnknownPathVariablesAreLocated) {
  EXPECT_THAT(
      ErrorOf(R"(name: x
algorithms: [{name: odo, adapter: odometry}]
sequences:
  - {name: mine, format: carmen, path: "${NOPE}/a.log", ground_truth: none}
)"),
      HasSubstr(Located(4, 5) + "sequences[0]: sequence 'mine': catalog path '${NOPE}/a.log': unknown variable"));
}

// Whatever the text, the reader answers with a SweepConfig or an InputError, never another exception.
TEST_F(SweepConfigTest, NeverFailsOtherwiseOnMalformedInput) {
  const std::string valid = std::string(kMinimal) + "noise: [{name: n, range: {sigma_m: 0.1}}]\n";
  std::vector<std::string> texts = {
      "",
      "~",
      "42",
      "[]",
      "{}",
      "name: {a: b}",
      "{[a]: 1}",
      "name: x\n[: y",
      "name: x\nalgorithms: [[1]]\nsequences: [lab]\n",
      "name: x\nalgorithms: [{name: [a], adapter: {b: c}}]\nsequences: [[lab]]\n",
      "name: x\nalgorithms: [{name: a, adapter: odometry, parameters: [1]}]\nsequences: [lab]\n",
      "name: x\nalgorithms: [{name: a, adapter: odometry}]\nsequences: [{catalog: [x]}]\n",
      "name: x\nalgorithms: [{name: a, adapter: odometry}]\nsequences: [lab]\nexclude: [{parameters: {[k]: 1}}]\n",
      "name: &a x\nalgorithms: *a\nsequences: [lab]\n",
      std::string("name: \t\0\x01", 9)};
  // Every prefix of a valid file, cut anywhere.
  for (std::size_t cut = 0; cut < valid.size(); cut += 3) texts.push_back(valid.substr(0, cut));
  for (const std::string& text : texts) {
    try {
      Parse(text);
    } catch (const evaluator::InputError&) {
    } catch (const std::exception& error) {
      ADD_FAILURE() << "'" << text << "': " << typeid(error).name() << ": " << error.what();
    }
  }
}

TEST_F(SweepConfigTest, SegmentLengthsAreAutoAListOrNone) {
  EXPECT_FALSE(Parse(kMinimal).evaluation.rpe_segments_m) << "default: 10-50 % of the reference path";
  EXPECT_FALSE(Parse(std::string(kMinimal) + "evaluation: {rpe_segments_m: auto}\n").evaluation.rpe_segments_m);
  const SweepConfig listed = Parse(std::string(kMinimal) + "evaluation: {rpe_segments_m: [20, 5, 2.5]}\n");
  ASSERT_TRUE(listed.evaluation.rpe_segments_m);
  EXPECT_EQ(*listed.evaluation.rpe_segments_m, (std::vector<double>{2.5, 5, 20}));  // ascending
  const SweepConfig none = Parse(std::string(kMinimal) + "evaluation: {rpe_segments_m: []}\n");
  ASSERT_TRUE(none.evaluation.rpe_segments_m);
  EXPECT_TRUE(none.evaluation.rpe_segments_m->empty());
  for (const char* bad : {"[5, 5]", "[0]", "[-1, 4]", "[ten]", "sometimes", "{a: 1}"}) {
    EXPECT_THAT(
        ErrorOf(std::string(kMinimal) + "evaluation: {rpe_segments_m: " + bad + "}\n"),
        HasSubstr(Located(6, 30) + "evaluation.rpe_segments_m: expected auto or a list of distinct segment lengths"))
        << bad;
  }
  // Thresholds may name a segment metric by its length.
  const SweepConfig judged =
      Parse(std::string(kMinimal) + "thresholds:\n  - {metric: segment_drift_10m, statistic: mean, max: 2}\n");
  EXPECT_EQ(judged.thresholds.at(0).metric, "segment_drift_10m");
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "thresholds:\n  - {metric: segment_drift, max: 2}\n"),
              HasSubstr("segment_trans|drift|rot_<length>m"));
}

TEST_F(SweepConfigTest, RegressionBlockIsOptionalStrictAndRangeChecked) {
  const SweepConfig defaults = Parse(kMinimal);
  EXPECT_DOUBLE_EQ(defaults.regression.alpha, 0.05);
  EXPECT_DOUBLE_EQ(defaults.regression.min_effect, 0.2);
  const SweepConfig set = Parse(std::string(kMinimal) + "regression: {alpha: 0.01, min_effect: 0.3}\n");
  EXPECT_DOUBLE_EQ(set.regression.alpha, 0.01);
  EXPECT_DOUBLE_EQ(set.regression.min_effect, 0.3);
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "regression: {alpha: 1.5}\n"),
              HasSubstr(Located(6, 21) + "regression.alpha: expected a significance level in (0, 1)"));
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "regression: {min_effect: -0.1}\n"),
              HasSubstr(Located(6, 26) + "regression.min_effect: expected a Cliff's delta magnitude in [0, 1]"));
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "regression: {alfa: 0.1}\n"), HasSubstr("alfa"));
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "regression: {alpha: often}\n"), HasSubstr("regression.alpha"));
}

TEST_F(SweepConfigTest, AValidityStudyIsAnchoredBesideTheFileAndMustExist) {
  EXPECT_TRUE(Parse(kMinimal).validity_study.empty());
  testing::WriteFile(dir_ / "study.json", "{}");
  const SweepConfig named = Parse(std::string(kMinimal) + "validity_study: study.json\n");
  EXPECT_EQ(named.validity_study, dir_.path() / "study.json");
  EXPECT_THAT(ErrorOf(std::string(kMinimal) + "validity_study: missing.json\n"),
              HasSubstr(Located(6, 17) + "validity_study: expected a summary.json of a sweep with reference data"));
}

}  // namespace
}  // namespace slamsweep::orchestrator
