// "Trustworthy comparisons" end to end, through `slamsweep run` as a user runs it: programs never
// see the reference, rows are never pooled across settings, stale results are not reused silently,
// and a sweep that cannot run stops before it starts.
#include <stdlib.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <vector>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli/run_cli.h"
#include "tests/support/shared_data.h"

namespace slamsweep {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using testing::RunCli;

const bool kTrustWorkerProgramSet = setenv("SLAMSWEEP_WORKER_PROGRAM", SLAMSWEEP_BINARY, 1) == 0;

std::string Fixture(const std::string& name) {
  return std::string(SLAMSWEEP_SOURCE_DIR) + "/tests/cli/echo_programs/" + name;
}

std::string ReadText(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

nlohmann::json ReadJsonFile(const std::filesystem::path& file) { return nlohmann::json::parse(ReadText(file)); }

/// A command algorithm that echoes one pose field of its CARMEN input as its trajectory.
std::string EchoAlgorithm(const std::string& name, const std::string& field) {
  return "  - name: " + name +
         "\n    adapter: command\n    timeout_s: 60\n    command:\n      argv: [awk, -v, field=" + field +
         ", -v, \"out={output_dir}/trajectory.tum\", -f, " + Fixture("echo_pose.awk") +
         ", \"{input}\"]\n      input_format: carmen\n      trajectory: {path: trajectory.tum, format: tum}\n"
         "      read_only: [" +
         Fixture("") + "]\n";
}

/// The headline value of `metric` for each algorithm of a sequence x noise table in summary.json.
std::map<std::string, double> GroupMeans(const nlohmann::json& summary, const std::string& sequence,
                                         const std::string& metric, const std::string& statistic) {
  std::map<std::string, double> means;
  for (const auto& group : summary.at("groups")) {
    if (group.at("sequence") != sequence || group.at("n_ok").get<int>() == 0) continue;
    const auto& metrics = group.at("metrics");
    if (!metrics.contains(metric)) continue;
    means[group.at("algorithm").get<std::string>()] = metrics.at(metric).at(statistic).at("mean").get<double>();
  }
  return means;
}

TEST(TrustTest, ProgramsThatEchoTheirInputPosesNeverBeatTheOdometryBaseline) {
  SLAMSWEEP_REQUIRE_SHARED(intel, "datasets/intel/intel-corrected.log.gz");
  testing::TempDir dir;
  std::string config =
      "name: echo\noutput: out\niterations: 1\nseed: 7\n"
      "evaluation: {align: se2, stages: 0}\n"
      "algorithms:\n"
      "  - name: odometry\n    adapter: odometry\n" +
      EchoAlgorithm("echo-flaser-pose", "flaser_pose") + EchoAlgorithm("echo-flaser-odom", "flaser_odom") +
      EchoAlgorithm("echo-robotlaser-robot", "robotlaser_robot") +
      EchoAlgorithm("echo-robotlaser-laser", "robotlaser_laser") + EchoAlgorithm("echo-odom", "odom") +
      "  - name: echo-tum\n    adapter: command\n    command:\n      argv: [" + Fixture("echo_tum.sh") +
      ", \"{input}\", \"{output_dir}\"]\n      input_format: tum\n      trajectory: {path: trajectory.tum, format: "
      "tum}\n"
      "sequences:\n"
      "  - {catalog: intel, name: intel-300, max_scans: 300}\n"
      "  - name: floor\n    format: simulated\n    ground_truth: exact\n"
      "    simulation: {floor_plan: {seed: 3, rooms_per_side: 1}, path: {rate_hz: 4.0}, noise_seed: 3}\n"
      "noise:\n  - name: noisy\n    odometry: {alpha1: 0.05, alpha2: 0.001, alpha3: 0.05, alpha4: 0.001}\n";
  const auto file = testing::WriteFile(dir / "echo.yaml", config);
  const auto run = RunCli({"run", file.string(), "--no-report", "-k"});
  // The FLASER echoes find no FLASER record in the floor's ROBOTLASER1 log and fail there, and the
  // reverse on intel: the sweep exits 1, but every echo scores where its field exists.
  ASSERT_LE(run.exit_code, 1) << run.out << run.err;
  const nlohmann::json summary = ReadJsonFile(dir / "out" / "summary.json");
  for (const std::string sequence : {"intel-300", "floor"}) {
    const auto means = GroupMeans(summary, sequence, "ape_trans", "rmse");
    ASSERT_TRUE(means.contains("odometry")) << sequence << "\n" << summary.dump(1);
    const double baseline = means.at("odometry");
    ASSERT_GT(baseline, 0.05) << sequence << ": the noisy odometry must give SLAM real work";
    std::size_t echoes = 0;
    for (const auto& [algorithm, ate] : means) {
      if (algorithm == "odometry") continue;
      ++echoes;
      // An echo of the odometry scores the odometry's ATE (up to the print precision and, for the
      // laser pose, the sensor mount): anything clearly better is the reference leaking.
      EXPECT_GE(ate, 0.99 * baseline) << sequence << ": " << algorithm << " scored ATE " << ate
                                      << " m against the odometry's " << baseline << " m";
      std::cout << "[ echo ] " << sequence << " " << algorithm << " ATE rmse " << ate << " m (odometry " << baseline
                << " m)\n";
    }
    // FLASER pose and odom, ODOM, TUM on intel; ROBOTLASER1 robot and laser, ODOM, TUM on the floor.
    EXPECT_GE(echoes, 4u) << sequence << ": too few echo programs produced a trajectory\n" << run.out;
  }

  // What the TUM echo could see while it ran: its own folder, no truth, no slamsweep variables.
  for (const auto& entry : std::filesystem::directory_iterator(dir / "out" / "runs")) {
    if (entry.path().filename().string().rfind("echo-tum-", 0) != 0) continue;
    const auto raw = entry.path() / "raw";
    EXPECT_EQ(ReadText(raw / "seen_cwd.txt"), std::filesystem::canonical(raw).string() + "\n");
    const std::string listing = ReadText(raw / "seen_run_folder.txt");
    EXPECT_THAT(listing, HasSubstr("input"));
    EXPECT_THAT(listing, Not(HasSubstr("reference")));
    EXPECT_THAT(listing, Not(HasSubstr("result.json")));
    EXPECT_THAT(ReadText(raw / "seen_environment.txt"), Not(HasSubstr("SLAMSWEEP_")));
    // Written once the program had exited.
    EXPECT_TRUE(std::filesystem::exists(entry.path() / "reference.tum"));
  }
}

TEST(TrustTest, RowsWithOtherParametersOrNoiseAreNeverPooled) {
  testing::TempDir dir;
  const std::string config =
      "name: groups\noutput: out\niterations: 2\nseed: 3\nevaluation: {stages: 0}\n"
      "algorithms:\n"
      "  - name: odometry\n    adapter: odometry\n"
      "  - name: echo\n    adapter: command\n    parameters: {gain: [1, 2, 3]}\n    command:\n      argv: [" +
      Fixture("echo_tum.sh") +
      ", \"{input}\", \"{output_dir}\", \"{param:gain}\"]\n      input_format: tum\n"
      "      trajectory: {path: trajectory.tum, format: tum}\n"
      "sequences:\n"
      "  - name: floor\n    format: simulated\n    ground_truth: exact\n"
      "    simulation: {floor_plan: {seed: 1, rooms_per_side: 1}, path: {rate_hz: 2.0}, noise_seed: 1}\n"
      "noise:\n  - name: low\n    odometry: {alpha1: 0.001}\n  - name: high\n    odometry: {alpha1: 0.02}\n";
  const auto file = testing::WriteFile(dir / "groups.yaml", config);
  const auto run = RunCli({"run", file.string()});
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;

  // (odometry + echo x 3 gains) x 2 noise levels = 8 groups of 2 iterations each.
  const std::string csv = ReadText(dir / "out" / "summary.csv");
  std::istringstream lines(csv);
  std::string header;
  std::getline(lines, header);
  EXPECT_THAT(header, HasSubstr("sequence,algorithm,parameters,noise,odometry,n_runs,n_ok"));
  EXPECT_THAT(header, HasSubstr("ape_trans.rmse.mean"));
  std::map<std::string, int> rows;
  for (std::string line; std::getline(lines, line);) {
    // sequence,algorithm,parameters,noise (the odometry mode dropped) before n_runs,n_ok
    const std::string group = line.substr(0, line.find(",2,2,"));
    ++rows[group.substr(0, group.rfind(','))];
    EXPECT_THAT(line, HasSubstr(",2,2,0,")) << line;  // n_runs 2, n_ok 2, n_failed 0
  }
  EXPECT_EQ(rows.size(), 8u) << csv;
  for (const char* group : {"floor,echo,gain=1,low", "floor,echo,gain=2,high", "floor,odometry,,high"}) {
    EXPECT_EQ(rows[group], 1) << group << "\n" << csv;
  }
  const std::string runs_csv = ReadText(dir / "out" / "runs.csv");
  EXPECT_EQ(std::count(runs_csv.begin(), runs_csv.end(), '\n'), 1 + 16) << runs_csv;

  // The report: one table per noise level, a row per gain (the varying parameter named in the row).
  const std::string index = ReadText(dir / "out" / "report" / "index.html");
  EXPECT_THAT(index, HasSubstr("floor, noise low"));
  EXPECT_THAT(index, HasSubstr("floor, noise high"));
  EXPECT_THAT(index, HasSubstr("echo [gain=3]"));
  EXPECT_THAT(index, HasSubstr("<title>groups</title>"));  // the sweep's name
  // JUnit names the group of every testcase.
  const std::string junit = ReadText(dir / "out" / "junit.xml");
  EXPECT_THAT(junit, HasSubstr("classname=\"floor.high\" name=\"echo [gain=2] i1 ("));
}

TEST(TrustTest, CorrectedLogsWithoutOdometryNoiseAreFlaggedEverywhere) {
  SLAMSWEEP_REQUIRE_SHARED(intel, "datasets/intel/intel-corrected.log.gz");
  testing::TempDir dir;
  const auto file = testing::WriteFile(
      dir / "clean.yaml",
      "name: clean\noutput: out\nevaluation: {stages: 0}\nalgorithms:\n  - {name: odometry, adapter: odometry}\n"
      "sequences:\n  - {catalog: intel, name: intel-50, max_scans: 50, odometry: reference}\n");
  const auto plan = RunCli({"plan", file.string()});
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  EXPECT_THAT(plan.err, HasSubstr("warning: 1 run on 'intel-50' with noise 'clean' get the reference as odometry"));
  EXPECT_THAT(plan.err, HasSubstr("odometry-intel-50-clean-i0-"));
  const auto run = RunCli({"run", file.string()});
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_THAT(run.err, HasSubstr("upper bound, not a SLAM result"));
  const nlohmann::json summary = ReadJsonFile(dir / "out" / "summary.json");
  EXPECT_EQ(summary.at("runs").at(0).at("odometry_is_reference"), true);
  EXPECT_EQ(summary.at("groups").at(0).at("odometry_is_reference"), true);
  for (const auto& entry : std::filesystem::directory_iterator(dir / "out" / "runs")) {
    EXPECT_EQ(ReadJsonFile(entry.path() / "run.json").at("odometry_is_reference"), true);
    EXPECT_EQ(ReadJsonFile(entry.path() / "result.json").at("odometry_is_reference"), true);
  }
  EXPECT_THAT(ReadText(dir / "out" / "report" / "index.html"),
              HasSubstr("odometry = reference: an upper bound, not a SLAM result"));
}

TEST(TrustTest, AChangedProgramIsRunAgainUnlessStaleResultsAreAllowed) {
  testing::TempDir dir;
  const auto program = testing::WriteFile(dir / "slam.sh", ReadText(Fixture("echo_tum.sh")));
  ::chmod(program.c_str(), 0755);
  const auto file = testing::WriteFile(
      dir / "stale.yaml",
      "name: stale\noutput: out\nevaluation: {stages: 0}\nalgorithms:\n  - name: echo\n    adapter: command\n"
      "    command:\n      argv: [./slam.sh, \"{input}\", \"{output_dir}\"]\n      input_format: tum\n"
      "      trajectory: {path: trajectory.tum, format: tum}\n"
      "sequences:\n  - name: floor\n    format: simulated\n    ground_truth: exact\n"
      "    simulation: {floor_plan: {seed: 1, rooms_per_side: 1}, path: {rate_hz: 2.0}, noise_seed: 1}\n");
  const auto first = RunCli({"run", file.string(), "--no-report"});
  ASSERT_EQ(first.exit_code, 0) << first.out << first.err;
  const auto same = RunCli({"run", file.string(), "--no-report"});
  EXPECT_THAT(same.out, HasSubstr("0 ok, 0 failed, 1 done earlier"));
  // The run folder names the program's digest: an edited wrapper is another program.
  const nlohmann::json plan = nlohmann::json::parse(RunCli({"plan", file.string(), "--json"}).out);
  EXPECT_THAT(plan.at(0).at("build").at("program_files").dump(), HasSubstr("slam.sh"));
  EXPECT_FALSE(plan.at(0).at("build").at("slamsweep_revision").get<std::string>().empty());
  testing::WriteFile(program, ReadText(program) + "# edited\n");
  const auto reused = RunCli({"run", file.string(), "--reuse-stale"});
  EXPECT_THAT(reused.out, HasSubstr("0 ok, 0 failed, 1 done earlier"));
  EXPECT_THAT(
      reused.out,
      HasSubstr(
          "1 earlier result computed by another slamsweep revision, program build or evaluation setting was reused"));
  // The reused run is marked stale in every output a reader or CI reads.
  const std::filesystem::path out = dir / "out";
  const nlohmann::json summary = ReadJsonFile(out / "summary.json");
  EXPECT_THAT(summary.at("runs").at(0).at("flags").dump(), HasSubstr("\"stale\""));
  EXPECT_THAT(summary.at("groups").at(0).at("flags").dump(), HasSubstr("\"stale\""));
  for (const char* table : {"summary.csv", "runs.csv"}) {
    const std::string csv = ReadText(out / table);
    const std::string header = csv.substr(0, csv.find('\n'));
    const std::string row = csv.substr(header.size() + 1);
    ASSERT_THAT(header, HasSubstr(",flags,")) << table;
    const auto column = std::count(header.begin(), header.begin() + header.find(",flags,") + 1, ',');
    std::string field;
    std::istringstream cells(row);
    for (long c = 0; c <= column; ++c) std::getline(cells, field, ',');
    EXPECT_THAT(field, HasSubstr("stale")) << table << "\n" << csv;
  }
  const std::string junit = ReadText(out / "junit.xml");
  EXPECT_THAT(junit, HasSubstr("<property name=\"flag\" value=\"stale\"/>"));
  EXPECT_THAT(junit, HasSubstr("stale: reused from an earlier sweep"));
  EXPECT_THAT(ReadText(out / "report" / "index.html"), HasSubstr("stale: reused from an earlier sweep"));
  const auto rerun = RunCli({"run", file.string(), "--no-report"});
  EXPECT_THAT(rerun.out, HasSubstr("1 ok, 0 failed, 0 done earlier"));
  EXPECT_THAT(rerun.out, HasSubstr("was run again"));
}

TEST(TrustTest, AProgramThatCannotBeIsolatedFailsItsRunUnlessAllowedAndIsThenFlaggedEverywhere) {
  testing::TempDir dir;
  const auto file = testing::WriteFile(
      dir / "open.yaml",
      "name: open\noutput: out\nevaluation: {stages: 0}\nalgorithms:\n  - name: echo\n    adapter: command\n"
      "    command:\n      argv: [" +
          Fixture("echo_tum.sh") +
          ", \"{input}\", \"{output_dir}\"]\n"
          "      input_format: tum\n      trajectory: {path: trajectory.tum, format: tum}\n"
          "sequences:\n  - name: floor\n    format: simulated\n    ground_truth: exact\n"
          "    simulation: {floor_plan: {seed: 1, rooms_per_side: 1}, path: {rate_hz: 2.0}, noise_seed: 1}\n");
  // A PATH with what the program calls but no bubblewrap: the workers started from here cannot make a sandbox.
  std::filesystem::create_directories(dir / "bin");
  for (const char* tool : {"cp", "pwd", "ls", "env", "sh"}) {
    std::filesystem::create_symlink(std::filesystem::path("/usr/bin") / tool, dir / "bin" / tool);
  }
  const std::string path = std::getenv("PATH");
  ::setenv("PATH", (dir.path() / "bin").c_str(), 1);
  const auto refused = RunCli({"run", file.string(), "--no-report"});
  const auto allowed =
      RunCli({"run", file.string(), "--no-report", "-o", (dir / "allowed").string(), "--allow-unisolated"});
  ::setenv("PATH", path.c_str(), 1);

  EXPECT_EQ(refused.exit_code, 1) << refused.out << refused.err;
  const nlohmann::json failed = ReadJsonFile(dir / "out" / "summary.json").at("runs").at(0);
  EXPECT_EQ(failed.at("status"), "failed");
  EXPECT_EQ(failed.at("failure_kind"), "not_isolated");
  EXPECT_THAT(failed.at("reason").get<std::string>(), HasSubstr("bubblewrap (bwrap) is not installed"));

  ASSERT_EQ(allowed.exit_code, 0) << allowed.out << allowed.err;
  const auto out = dir / "allowed";
  const nlohmann::json run = ReadJsonFile(out / "summary.json").at("runs").at(0);
  EXPECT_EQ(run.at("status"), "ok");
  EXPECT_EQ(run.at("flags"), nlohmann::json::array({"unisolated"}));
  const auto run_dir = out / "runs" / run.at("run_id").get<std::string>();
  EXPECT_EQ(ReadJsonFile(run_dir / "run.json").at("allow_unisolated"), true);
  EXPECT_EQ(ReadJsonFile(run_dir / "result.json").at("flags"), nlohmann::json::array({"unisolated"}));
  EXPECT_THAT(ReadText(out / "runs.csv"), HasSubstr("unisolated"));
  EXPECT_THAT(ReadText(out / "summary.csv"), HasSubstr("unisolated"));
  EXPECT_THAT(ReadText(out / "junit.xml"), HasSubstr("<property name=\"flag\" value=\"unisolated\"/>"));
}

TEST(TrustTest, RbpfSlamWithTheSameSeedGivesTheSameTrajectory) {
  SLAMSWEEP_REQUIRE_SHARED(intel, "datasets/intel/intel-corrected.log.gz");
  if (std::system("command -v rbpf-slam > /dev/null") != 0)
    SLAMSWEEP_SKIP_OR_FAIL_IN_CI("rbpf-slam not installed (mrpt-apps)");
  testing::TempDir dir;
  // seed_policy fixed: both iterations get the same seed, hence the same noisy input and RANDOM_SEED.
  const std::string config =
      "name: rbpf\noutput: OUT\niterations: 2\nseed: SEED\nseed_policy: fixed\nevaluation: {stages: 0}\n"
      "algorithms:\n  - {name: rbpf, adapter: mrpt-rbpf-slam, parameters: {MappingApplication.sampleSize: 5}}\n"
      "sequences:\n  - {catalog: intel, name: intel-120, max_scans: 120}\n"
      "noise:\n  - name: noisy\n    odometry: {alpha1: 0.02, alpha3: 0.02}\n";
  const auto with = [&](const std::string& out, const std::string& seed) {
    std::string text = config;
    text.replace(text.find("OUT"), 3, out);
    text.replace(text.find("SEED"), 4, seed);
    return testing::WriteFile(dir / (out + ".yaml"), text);
  };
  const auto run = RunCli({"run", with("out", "11").string(), "--no-report"});
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  std::vector<std::string> trajectories;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "out" / "runs")) {
    trajectories.push_back(ReadText(entry.path() / "trajectory.tum"));
    EXPECT_EQ(ReadJsonFile(entry.path() / "run.json").at("seeding"), "seeded");
  }
  ASSERT_EQ(trajectories.size(), 2u);
  EXPECT_GT(trajectories[0].size(), 1000u);
  EXPECT_EQ(trajectories[0], trajectories[1]) << "same seed, same input: rbpf-slam must give the same trajectory";
  // Another seed gives another noisy input and another draw: the seed does reach the program.
  ASSERT_EQ(RunCli({"run", with("out2", "12").string(), "--no-report", "--iterations", "1"}).exit_code, 0);
  for (const auto& entry : std::filesystem::directory_iterator(dir / "out2" / "runs")) {
    EXPECT_NE(ReadText(entry.path() / "trajectory.tum"), trajectories[0]);
  }
}

TEST(TrustTest, ASweepThatCannotRunStopsAtPlanTimeNamingTheLine) {
  testing::TempDir dir;
  const std::string head = "name: bad\nalgorithms:\n  - name: x\n    adapter: command\n    command:\n      argv: [";
  const std::string tail =
      "]\n      input_format: tum\n      trajectory: {path: t.tum, format: tum}\nsequences:\n  - name: floor\n"
      "    format: simulated\n    ground_truth: exact\n    simulation: {floor_plan: {seed: 1}}\n";
  const auto plan = [&](const std::string& argv) {
    return RunCli({"plan", testing::WriteFile(dir / "bad.yaml", head + argv + tail).string()});
  };
  const auto missing = plan("no-such-slam-program, \"{input}\"");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_THAT(missing.err, HasSubstr("bad.yaml:6:"));
  EXPECT_THAT(missing.err,
              HasSubstr("algorithms[0].command.argv[0]: program 'no-such-slam-program' not found in PATH"));
  testing::WriteFile(dir / "not-executable.sh", "#!/bin/sh\n");
  const auto not_executable = plan("./not-executable.sh");
  EXPECT_EQ(not_executable.exit_code, 2);
  EXPECT_THAT(not_executable.err, HasSubstr("not-executable.sh: not executable"));
  const auto unknown = plan("true, \"{run_dir}\"");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_THAT(unknown.err, HasSubstr("bad.yaml:6:"));
  EXPECT_THAT(unknown.err, HasSubstr("algorithms[0].command.argv[1]: unknown placeholder {run_dir}"));
  const auto unbalanced = plan("true, \"{input\"");
  EXPECT_EQ(unbalanced.exit_code, 2);
  EXPECT_THAT(unbalanced.err, HasSubstr("'{' without its closing '}'"));
  const auto lone = plan("true, \"a}b\"");
  EXPECT_EQ(lone.exit_code, 2);
  EXPECT_THAT(lone.err, HasSubstr("a lone '}'"));
  // Doubled braces are literal braces, for the check and for the expansion alike.
  const auto escaped = plan("true, \"{{input}}\", \"{seed32}\"");
  EXPECT_EQ(escaped.exit_code, 0) << escaped.err;
  const nlohmann::json runs = nlohmann::json::parse(RunCli({"plan", (dir / "bad.yaml").string(), "--json"}).out);
  EXPECT_EQ(runs.at(0).at("seeding"), "seeded");
}

/// A metric statistic of a run's result.json ("ape_trans", "rmse"); NaN when absent.
double ResultMetric(const nlohmann::json& result, const std::string& name, const std::string& statistic) {
  for (const nlohmann::json& metric : result.at("metrics")) {
    if (metric.at("metric") == name && metric.at("statistic") == statistic) return metric.at("value").get<double>();
  }
  return std::numeric_limits<double>::quiet_NaN();
}

TEST(TrustTest, OdometryBaselineOnIntelsRecordedOdometryIsNoUpperBound) {
  SLAMSWEEP_REQUIRE_SHARED(intel, "datasets/intel/intel-corrected.log.gz");
  testing::TempDir dir;
  // The catalog's default: the robot's recorded odometry, no noise.
  const auto file = testing::WriteFile(
      dir / "recorded.yaml",
      "name: recorded\noutput: out\nevaluation: {stages: 0}\nalgorithms:\n  - {name: odometry, adapter: odometry}\n"
      "sequences:\n  - intel\n");
  const auto plan = RunCli({"plan", file.string()});
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  EXPECT_THAT(plan.err, Not(HasSubstr("get the reference as odometry")));
  const auto run = RunCli({"run", file.string()});
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  const nlohmann::json summary = ReadJsonFile(dir / "out" / "summary.json");
  EXPECT_EQ(summary.at("runs").at(0).at("odometry_is_reference"), false);
  std::size_t runs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "out" / "runs")) {
    ++runs;
    const nlohmann::json result = ReadJsonFile(entry.path() / "result.json");
    EXPECT_EQ(result.at("odometry_is_reference"), false);
    // Dead reckoning on the wheels drifts tens of metres from the corrected path (21 m on average).
    EXPECT_GT(ResultMetric(result, "ape_trans", "rmse"), 5.0);
    // The relations: nearly all used, and the odometry far worse than the corrected log itself.
    const double used = ResultMetric(result, "relations_trans", "n");
    const double not_covered = ResultMetric(result, "relations_trans", "not_covered");
    EXPECT_GE(used / (used + not_covered), 0.95);
    EXPECT_GT(ResultMetric(result, "relations_trans", "mean"), 1.0);
    ASSERT_TRUE(result.contains("reference_floor")) << result.dump();
    double floor_m = std::numeric_limits<double>::quiet_NaN();
    for (const nlohmann::json& metric : result.at("reference_floor").at("metrics")) {
      if (metric.at("metric") == "relations_trans" && metric.at("statistic") == "mean") floor_m = metric.at("value");
    }
    EXPECT_LT(floor_m, 0.2);
  }
  EXPECT_EQ(runs, 1u);
}

// A raw log with relations as its only reference: the program's odometry is the robot's (never flagged as the
// reference), there is no ATE to compute, and the relations outside the cut log are counted apart.
TEST(TrustTest, TheFullRateIntelLogIsRawAndScoredOnTheRelationsInsideIt) {
  SLAMSWEEP_REQUIRE_SHARED(raw, "datasets/intel/intel-raw-scans-0-5504.clf.gz");
  SLAMSWEEP_REQUIRE_SHARED(relations, "datasets/intel/intel.relations");
  testing::TempDir dir;
  const auto file = testing::WriteFile(
      dir / "raw.yaml",
      "name: raw\noutput: out\nevaluation: {stages: 0}\nalgorithms:\n  - {name: odometry, adapter: odometry}\n"
      "sequences:\n  - {catalog: intel-full-rate, name: intel-full-rate-800, max_scans: 800}\n");
  const auto plan = RunCli({"plan", file.string()});
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  EXPECT_THAT(plan.err, Not(HasSubstr("get the reference as odometry")));
  const auto run = RunCli({"run", file.string()});
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  const nlohmann::json summary = ReadJsonFile(dir / "out" / "summary.json");
  EXPECT_EQ(summary.at("runs").at(0).at("odometry_is_reference"), false);
  std::size_t runs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "out" / "runs")) {
    ++runs;
    const nlohmann::json result = ReadJsonFile(entry.path() / "result.json");
    EXPECT_EQ(result.at("status"), "ok") << result.dump();
    EXPECT_EQ(result.at("odometry_is_reference"), false);
    EXPECT_TRUE(std::isnan(ResultMetric(result, "ape_trans", "rmse"))) << "no reference trajectory, no ATE";
    const double used = ResultMetric(result, "relations_trans", "n");
    const double not_covered = ResultMetric(result, "relations_trans", "not_covered");
    const double outside = ResultMetric(result, "relations_trans", "outside_log");
    EXPECT_GT(used, 50.0);
    EXPECT_EQ(not_covered, 0.0) << "the baseline's path spans the whole cut";
    EXPECT_EQ(used + not_covered + outside, 2984.0);
    EXPECT_EQ(result.at("metric_details").at("coverage").at("basis"), "relations");
    EXPECT_EQ(result.at("metric_details").at("coverage").at("fraction"), 1.0);
    EXPECT_GT(ResultMetric(result, "relations_trans", "mean"), 0.0);
    EXPECT_FALSE(result.contains("reference_floor"));
    EXPECT_EQ(result.at("sequence").at("stamps").at("outcome"), "retimed");
    EXPECT_GT(result.at("sequence").at("stamps").at("steps_back").get<int>(), 0);
  }
  EXPECT_EQ(runs, 1u);
}

}  // namespace
}  // namespace slamsweep
