// The roster through `slamsweep run`, as a user runs it: each built algorithm on intel's first 300
// scans with noisy odometry must end below the odometry baseline's ATE and produce a map the paper's
// metrics score; a misspelt parameter is a failed run naming it, not a silent default.
#include <stdlib.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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
  // CI builds gmapping, slam-constructor's two and Hector from ../shared/peers (scripts/test.sh);
  // Cartographer is opt-in (SLAMSWEEP_ROSTER=all). A CI run without them would test nothing.
  if (!slamsweep::testing::RunningInCi()) GTEST_SKIP() << "only checked under CI=true";
  const std::vector<std::string> built = BuiltRoster();
  for (const std::string name : {"gmapping", "tinyslam", "vinyslam", "hector"}) {
    EXPECT_NE(std::find(built.begin(), built.end(), name), built.end()) << name << " driver not built";
  }
}

TEST(RosterSweepTest, EveryBuiltAlgorithmBeatsNoisyOdometryOnIntel) {
  SLAMSWEEP_REQUIRE_SHARED(intel, "datasets/intel/intel-corrected.log.gz");
  const std::vector<std::string> built = BuiltRoster();
  if (built.empty()) GTEST_SKIP() << "no roster driver built: scripts/install-slam.sh && scripts/build.sh";
  slamsweep::testing::TempDir dir;
  std::string config =
      // Three noise draws: one draw decides little (on intel's first 300 scans the baseline's ATE
      // ranges 1.7 to 4.6 m over these seeds), the mean over three is what is compared.
      "name: roster\noutput: out\niterations: 3\nseed: 7\nworkers: 2\n"
      "evaluation: {align: se2, stages: 3}\n"
      "algorithms:\n  - name: odometry\n    adapter: odometry\n"
      "  - name: gmapping-misspelt\n    adapter: gmapping\n    parameters: {particels: 30}\n";
  for (const std::string& name : built) config += "  - name: " + name + "\n    adapter: " + name + "\n    timeout_s: 600\n";
  config +=
      "sequences:\n  - {catalog: intel, name: intel-300, max_scans: 300}\n"
      // configs/paper-noise.yaml's noise: 5 % standard deviation on turns and distances, a heading random
      // walk of 1.1 deg per sqrt(m). It makes the odometry drift metres on 300 scans.
      "noise:\n  - name: noisy\n    odometry: {alpha1: 0.0025, alpha2: 0.0004, alpha3: 0.0025, alpha4: 0.0001}\n";
  const auto file = slamsweep::testing::WriteFile(dir / "roster.yaml", config);
  const auto run = RunCli({"run", file.string(), "--no-report", "-k"});
  ASSERT_LE(run.exit_code, 1) << run.out << run.err;
  const nlohmann::json summary = ReadJson(dir / "out" / "summary.json");

  const nlohmann::json* odometry = GroupOf(summary, "odometry");
  ASSERT_NE(odometry, nullptr) << summary.dump(1);
  const double baseline = odometry->at("metrics").at("ape_trans").at("rmse").at("mean").get<double>();
  ASSERT_GT(baseline, 2.0) << "the noisy odometry must give SLAM real work";
  for (const std::string& name : built) {
    const nlohmann::json* group = GroupOf(summary, name);
    ASSERT_NE(group, nullptr) << name;
    ASSERT_EQ(group->at("n_ok").get<int>(), 3) << name << " failed:\n" << summary.dump(1);
    const auto& metrics = group->at("metrics");
    const double ate = metrics.at("ape_trans").at("rmse").at("mean").get<double>();
    std::cout << "[ roster ] " << name << " ATE rmse " << ate << " m (odometry " << baseline << " m)\n";
    if (name == "vinyslam") {
      // slam-constructor's vinySLAM with its upstream properties does not beat this odometry on
      // intel's sparse corrected log (scans about 1 m apart): measured over these three draws,
      // 1.4x the odometry's mean ATE (0.4x to 4x per draw), and a wider Monte-Carlo search makes it
      // worse (issue 14's note). It must still track the robot, not diverge.
      EXPECT_LT(ate, 2.0 * baseline) << name;
    } else {
      EXPECT_LT(ate, baseline) << name;
    }
    for (const char* metric : {"occupied_to_free_unknown", "corners", "enclosed_areas"}) {
      EXPECT_TRUE(metrics.contains(metric)) << name << " has no " << metric;
    }
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
  for (const std::string name : {"gmapping", "tinyslam", "vinyslam", "hector", "cartographer"}) {
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
  if (std::find(built.begin(), built.end(), "vinyslam") != built.end()) {
    // slam-constructor's parameters are the properties of its file, under their own names.
    EXPECT_TRUE(by_adapter.at("vinyslam").at("parameters").contains("slam/mapping/blur")) << by_adapter.at("vinyslam").dump();
  }
}

TEST(RosterSweepTest, TheCommandAdapterExampleRunsARealProgramLikeItsBuiltInAdapter) {
  SLAMSWEEP_REQUIRE_SHARED(intel, "datasets/intel/intel-corrected.log.gz");
  const std::vector<std::string> built = BuiltRoster();
  if (std::find(built.begin(), built.end(), "hector") == built.end()) {
    GTEST_SKIP() << "the example runs the Hector driver: scripts/install-slam.sh hector && scripts/build.sh";
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
