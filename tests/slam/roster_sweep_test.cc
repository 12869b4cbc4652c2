// The roster through `slamsweep run`, as a user runs it: each built algorithm's claim, to beat the
// odometry it was given, tested with a one-sided sign test over ten seeded noise draws (an algorithm
// upstream cannot make do that is listed with its measured numbers in roster_expected_failures.json,
// and the test fails when it starts passing); a program that echoes its odometry is the negative
// control that must fail; every built algorithm's map is scored; a misspelt parameter is a failed run
// naming it, not a silent default.
#include <stdlib.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <string_view>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "evaluator/statistics/sign_test.h"
#include "tests/cli/run_cli.h"
#include "tests/support/shared_data.h"

namespace slamsweep {
namespace {

using ::testing::HasSubstr;
using testing::RunCli;

const bool kWorkerProgramSet = setenv("SLAMSWEEP_WORKER_PROGRAM", SLAMSWEEP_BINARY, 1) == 0;

/// The roster drivers this build has (ROSTER_BUILT, from tests/slam/CMakeLists.txt).
std::vector<std::string> BuiltRoster() {
  std::vector<std::string> names;
  std::istringstream list(ROSTER_BUILT);
  for (std::string name; std::getline(list, name, ',');) {
    if (!name.empty()) names.push_back(name);
  }
  return names;
}

nlohmann::json ReadJson(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

const nlohmann::json* GroupOf(const nlohmann::json& summary, const std::string& algorithm) {
  for (const auto& group : summary.at("groups")) {
    if (group.at("algorithm") == algorithm) return &group;
  }
  return nullptr;
}

TEST(RosterSweepTest, CiBuildsTheRosterItPromises) {
  // CI builds the whole roster, Cartographer, slam_toolbox and LaMa included, from ../shared/peers
  // (scripts/test.sh). A CI run without one of them would test nothing about it.
  if (!slamsweep::testing::RunningInCi()) GTEST_SKIP() << "only checked under CI=true";
  const std::vector<std::string> built = BuiltRoster();
  for (const std::string name :
       {"gmapping", "tinyslam", "vinyslam", "hector", "cartographer", "slam-toolbox", "lama", "lama-pf"}) {
    EXPECT_NE(std::find(built.begin(), built.end(), name), built.end()) << name << " driver not built";
  }
}

// The roster test's input, stated once. intel's first kRosterScans scans (the test's CPU budget: about
// 3 CPU-minutes for all of it), kDraws seeded draws of mild odometry noise, the error is the ATE (se2
// RMSE) against intel's corrected poses. kOdometry is the odometry the noise is drawn on.
constexpr int kRosterScans = 200;
constexpr int kDraws = 10;
constexpr double kSignificance = 0.05;  // one-sided sign test: 9 wins of 10 draws
constexpr const char* kSequence = "intel-200";
constexpr const char* kNoise = "mild-odometry";
// The robot's recorded wheel odometry (the catalog's default on corrected logs), with the noise drawn on top.
// Changing it means measuring roster_expected_failures.json again: its entries name the odometry they
// were measured on.
constexpr std::string_view kOdometry = "recorded";

/// The ATE of every draw of `algorithm` (NaN for a failed run), by iteration.
std::vector<double> AteByDraw(const nlohmann::json& summary, const std::string& algorithm) {
  std::vector<double> ate(kDraws, std::nan(""));
  for (const auto& run : summary.at("runs")) {
    if (run.at("algorithm") != algorithm || run.at("status") != "ok") continue;
    const int iteration = run.at("iteration").get<int>();
    if (iteration >= 0 && iteration < kDraws && run.at("metrics").contains("ape_trans")) {
      ate[iteration] = run.at("metrics").at("ape_trans").at("rmse").get<double>();
    }
  }
  return ate;
}

double Mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

/// An algorithm upstream cannot make beat the odometry on this input (roster_expected_failures.json).
struct ExpectedFailure {
  std::string algorithm;
  std::string reason;
};

std::map<std::string, ExpectedFailure> ReadExpectedFailures() {
  const std::filesystem::path file =
      std::filesystem::path(SLAMSWEEP_SOURCE_DIR) / "tests/slam/roster_expected_failures.json";
  const nlohmann::json list = ReadJson(file);
  std::map<std::string, ExpectedFailure> failures;
  for (const auto& entry : list.at("expected_failures")) {
    // An entry measured on another input says nothing about this one: the list must follow the test.
    EXPECT_EQ(entry.at("sequence"), kSequence) << file << ": " << entry.dump();
    EXPECT_EQ(entry.at("noise"), kNoise) << file << ": " << entry.dump();
    EXPECT_EQ(entry.at("odometry"), kOdometry) << file << ": " << entry.dump();
    EXPECT_TRUE(entry.at("measured").contains("wins")) << entry.dump();
    failures[entry.at("algorithm")] = {entry.at("algorithm"), entry.at("reason")};
  }
  return failures;
}

TEST(RosterSweepTest, EveryBuiltAlgorithmBeatsTheOdometryItWasGivenByASignTest) {
  SLAMSWEEP_REQUIRE_SHARED(intel, "datasets/intel/intel-corrected.log.gz");
  const std::vector<std::string> built = BuiltRoster();
  if (built.empty())
    SLAMSWEEP_SKIP_OR_FAIL_IN_CI("no roster driver built: scripts/install-slam.sh && scripts/build.sh");
  slamsweep::testing::TempDir dir;
  std::string config =
      "name: roster\noutput: out\niterations: " + std::to_string(kDraws) +
      "\nseed: 7\nworkers: 2\nevaluation: {align: se2, stages: 0}\n"
      "algorithms:\n  - name: odometry\n    adapter: odometry\n"
      // The negative control: a program that hands back its odometry must fail the test.
      "  - name: echo-odometry\n    adapter: command\n    command:\n"
      "      argv: [" +
      std::string(SLAMSWEEP_SOURCE_DIR) +
      "/tests/slam/echo_odometry.sh, \"{input}\", "
      "\"{output_dir}\"]\n      input_format: tum\n      trajectory: {path: trajectory.tum, format: tum}\n"
      "  - name: gmapping-misspelt\n    adapter: gmapping\n    parameters: {particels: 30}\n";
  for (const std::string& name : built)
    config += "  - name: " + name + "\n    adapter: " + name + "\n    timeout_s: 600\n";
  config += "sequences:\n  - {catalog: intel, name: " + std::string(kSequence) +
            ", max_scans: " + std::to_string(kRosterScans) + ", odometry: " + std::string(kOdometry) +
            "}\n"
            // The quick start's mild odometry noise (the alphas are variances: 4.5 % of each distance
            // and turn, 0.6 deg per metre), one seeded draw per iteration, the same draw for every algorithm.
            "noise:\n  - name: " +
            std::string(kNoise) + "\n    odometry: {alpha1: 0.002, alpha2: 0.0001, alpha3: 0.002, alpha4: 0.0001}\n";
  const auto file = slamsweep::testing::WriteFile(dir / "roster.yaml", config);
  const auto run = RunCli({"run", file.string(), "--no-report", "-k"});
  ASSERT_LE(run.exit_code, 1) << run.out << run.err;
  const nlohmann::json summary = ReadJson(dir / "out" / "summary.json");

  const std::vector<double> odometry = AteByDraw(summary, "odometry");
  for (double ate : odometry) ASSERT_FALSE(std::isnan(ate)) << "the odometry baseline failed:\n" << summary.dump(1);
  const std::size_t wins_needed = evaluator::SignTestWinsNeeded(kDraws, kSignificance);
  ASSERT_EQ(wins_needed, 9u);
  const std::map<std::string, ExpectedFailure> expected_failures = ReadExpectedFailures();
  std::vector<std::string> judged = built;
  judged.push_back("echo-odometry");
  for (const std::string& name : judged) {
    std::vector<double> ate = AteByDraw(summary, name);
    std::size_t failed_runs = 0;
    for (double& value : ate) {
      // A failed draw is a loss, never a tie.
      if (std::isnan(value)) {
        value = std::numeric_limits<double>::infinity();
        ++failed_runs;
      }
    }
    const evaluator::SignTestResult test = evaluator::OneSidedSignTest(ate, odometry);
    const bool beats = test.p_value <= kSignificance;
    std::cout << "[ roster ] " << name << ": " << test.wins << " wins, " << test.losses << " losses, " << test.ties
              << " ties of " << kDraws << " draws (" << failed_runs << " failed runs), one-sided p = " << test.p_value
              << "; mean ATE " << Mean(ate) << " m against the odometry's " << Mean(odometry) << " m\n";
    if (name == "echo-odometry") {
      EXPECT_FALSE(beats) << "the negative control passes: the test cannot tell SLAM from its odometry";
      EXPECT_EQ(test.ties, static_cast<std::size_t>(kDraws)) << "the echo must score exactly the baseline";
    } else if (const auto listed = expected_failures.find(name); listed != expected_failures.end()) {
      EXPECT_FALSE(beats) << name << " is listed in tests/slam/roster_expected_failures.json (" << listed->second.reason
                          << ") but now beats the odometry: take it off the list";
    } else {
      EXPECT_TRUE(beats) << name << " does not beat the odometry it was given (" << test.wins << " of " << kDraws
                         << " draws, " << wins_needed << " needed)";
    }
    for (const char* metric : {"occupied_to_free_unknown", "corners", "enclosed_areas"}) {
      if (name == "echo-odometry" || failed_runs == static_cast<std::size_t>(kDraws)) continue;
      for (const auto& group : summary.at("groups")) {
        if (group.at("algorithm") == name) {
          EXPECT_TRUE(group.at("metrics").contains(metric)) << name << " has no " << metric;
        }
      }
    }
  }
  for (const auto& [name, failure] : expected_failures) {
    EXPECT_NE(std::find(built.begin(), built.end(), name), built.end()) << name << " is listed but not built here";
  }

  // The misspelt parameter: a failed run whose reason names it (the driver's message, via the log).
  bool found = false;
  for (const auto& entry : summary.at("runs")) {
    if (entry.at("algorithm") != "gmapping-misspelt") continue;
    found = true;
    EXPECT_EQ(entry.at("status"), "failed");
    const std::string log_text = [&] {
      std::ifstream in(dir / "out" / "runs" / entry.at("run_id").get<std::string>() / "log.txt");
      std::stringstream text;
      text << in.rdbuf();
      return text.str();
    }();
    EXPECT_THAT(log_text, HasSubstr("unknown parameter(s) for slamsweep-slam-gmapping: particels"));
  }
  EXPECT_TRUE(found || std::find(built.begin(), built.end(), "gmapping") == built.end());
}

TEST(RosterSweepTest, AlgorithmsListsEveryAdapterWithWhatIsInstalled) {
  const auto run = RunCli({"algorithms", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json list = nlohmann::json::parse(run.out);
  std::map<std::string, nlohmann::json> by_adapter;
  for (const auto& entry : list) by_adapter[entry.at("adapter").get<std::string>()] = entry;
  for (const char* adapter : {"gmapping", "tinyslam", "vinyslam", "hector", "cartographer", "mrpt-icp-slam",
                              "mrpt-rbpf-slam", "odometry", "command"}) {
    ASSERT_TRUE(by_adapter.contains(adapter)) << adapter << "\n" << run.out;
  }
  const std::vector<std::string> built = BuiltRoster();
  for (const std::string name :
       {"gmapping", "tinyslam", "vinyslam", "hector", "cartographer", "slam-toolbox", "lama", "lama-pf"}) {
    const nlohmann::json& entry = by_adapter.at(name);
    const bool is_built = std::find(built.begin(), built.end(), name) != built.end();
    EXPECT_EQ(entry.at("installed").get<bool>(), is_built) << entry.dump();
    if (!is_built) {
      EXPECT_THAT(entry.at("status").get<std::string>(), HasSubstr("scripts/install-slam.sh")) << entry.dump();
    }
  }
  if (std::find(built.begin(), built.end(), "gmapping") != built.end()) {
    const nlohmann::json& gmapping = by_adapter.at("gmapping");
    EXPECT_EQ(gmapping.at("license"), "BSD");
    EXPECT_EQ(gmapping.at("seeding"), "seeded");
    EXPECT_EQ(gmapping.at("parameters").at("particles"), "30");
    EXPECT_THAT(gmapping.at("status").get<std::string>(), HasSubstr("5105476edb12"));
  }
  // Defaults chosen on intel say so, with the re-check on a sequence they were not tuned on.
  for (const char* tuned : {"mrpt-icp-slam", "cartographer"}) {
    const std::string note = by_adapter.at(tuned).at("defaults_note").get<std::string>();
    EXPECT_THAT(note, HasSubstr("intel")) << tuned;
    EXPECT_THAT(note, HasSubstr("re-checked on the simulated floor")) << tuned;
  }
  EXPECT_EQ(by_adapter.at("gmapping").at("defaults_note"), "");
  if (std::find(built.begin(), built.end(), "vinyslam") != built.end()) {
    // slam-constructor's parameters are the properties of its file, under their own names.
    EXPECT_TRUE(by_adapter.at("vinyslam").at("parameters").contains("slam/mapping/blur"))
        << by_adapter.at("vinyslam").dump();
  }
}

TEST(RosterSweepTest, TheCommandAdapterExampleRunsARealProgramLikeItsBuiltInAdapter) {
  SLAMSWEEP_REQUIRE_SHARED(intel, "datasets/intel/intel-corrected.log.gz");
  const std::vector<std::string> built = BuiltRoster();
  if (std::find(built.begin(), built.end(), "hector") == built.end()) {
    SLAMSWEEP_SKIP_OR_FAIL_IN_CI(
        "the example runs the Hector driver: scripts/install-slam.sh hector && scripts/build.sh");
  }
  slamsweep::testing::TempDir dir;
  std::ifstream in(std::string(SLAMSWEEP_SOURCE_DIR) + "/configs/examples/command-adapter.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string config = text.str();
  // The example names the driver relative to the default build folder; this build may be elsewhere.
  const std::string written = "../../build/slam/bin/slamsweep-slam-hector";
  const std::size_t at = config.find(written);
  ASSERT_NE(at, std::string::npos) << "the example no longer runs the Hector driver";
  config.replace(at, written.size(), HECTOR_DRIVER);
  const auto file = slamsweep::testing::WriteFile(dir / "example.yaml", config + "output: out\n");
  const auto run = RunCli({"run", file.string(), "--no-report"});
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  const nlohmann::json summary = ReadJson(dir / "out" / "summary.json");
  const nlohmann::json* command = GroupOf(summary, "hector-as-command");
  const nlohmann::json* builtin = GroupOf(summary, "hector");
  ASSERT_NE(command, nullptr);
  ASSERT_NE(builtin, nullptr);
  // The same deterministic program on the same input: the same trajectory and map, whichever adapter ran it.
  for (const char* metric : {"ape_trans", "corners", "enclosed_areas"}) {
    EXPECT_EQ(command->at("metrics").at(metric), builtin->at("metrics").at(metric)) << metric;
  }
}

}  // namespace
}  // namespace slamsweep
