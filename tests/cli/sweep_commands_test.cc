// `slamsweep plan|run|merge|report` in-process, as the Jenkins scripts call them.
#include <stdlib.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/sweep_loading.h"
#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "tests/cli/run_cli.h"
#include "tests/support/shared_data.h"
#include "tests/support/sparse_carmen_log.h"

namespace slamsweep {
namespace {

using ::testing::HasSubstr;
using testing::RunCli;

/// Workers are started as a program: inside this test binary that must be the real slamsweep.
const bool kWorkerProgramSet = setenv("SLAMSWEEP_WORKER_PROGRAM", SLAMSWEEP_BINARY, 1) == 0;

std::string Repo(const std::string& relative) { return std::string(SLAMSWEEP_SOURCE_DIR) + "/" + relative; }

nlohmann::json ReadJson(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return nlohmann::json::parse(text.str());
}

std::size_t CountLines(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) count += line.find(part) != std::string::npos ? 1 : 0;
  return count;
}

TEST(PlanCommand, ListsTheQuickstartMatrixAndItsSelections) {
  const auto all = RunCli({"plan", Repo("configs/quickstart.yaml")});
  ASSERT_EQ(all.exit_code, 0) << all.err;
  // 3 algorithms x 2 sequences x 1 noise x 3 iterations, one line each, then the count.
  EXPECT_THAT(all.out, HasSubstr("18 runs"));
  const auto some = RunCli({"plan", Repo("configs/quickstart.yaml"), "--only-algorithms", "odometry,icp-slam",
                            "--only-sequences", "floor", "--iterations", "1", "--json"});
  ASSERT_EQ(some.exit_code, 0) << some.err;
  const nlohmann::json runs = nlohmann::json::parse(some.out);
  ASSERT_EQ(runs.size(), 2u);
  for (const auto& run : runs) {
    EXPECT_EQ(run["sequence"]["name"], "floor");
    EXPECT_EQ(run["iteration"], 0);
  }
}

TEST(PlanCommand, ASelectionKeepsRunIdsSoAShortSweepSharesResultsWithTheLongOne) {
  const auto full = nlohmann::json::parse(RunCli({"plan", Repo("configs/quickstart.yaml"), "--json"}).out);
  const auto first =
      nlohmann::json::parse(RunCli({"plan", Repo("configs/quickstart.yaml"), "--json", "--iterations", "1"}).out);
  std::set<std::string> ids;
  for (const auto& run : full) ids.insert(run["run_id"].get<std::string>());
  ASSERT_EQ(first.size(), 6u);
  for (const auto& run : first) EXPECT_EQ(ids.count(run["run_id"].get<std::string>()), 1u) << run["run_id"];
}

TEST(PlanCommand, UnknownNamesAndBadConfigsExitTwoNamingTheProblem) {
  const auto unknown = RunCli({"plan", Repo("configs/quickstart.yaml"), "--only-algorithms", "gmapping"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_THAT(unknown.err, HasSubstr("--only-algorithms: no 'gmapping' in the config (it has: icp-slam"));
  slamsweep::testing::TempDir dir;
  const auto config = slamsweep::testing::WriteFile(dir / "bad.yaml", "name: bad\niterations: two\n");
  const auto bad = RunCli({"plan", config.string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.err, HasSubstr("bad.yaml:2:"));
  EXPECT_THAT(bad.err, HasSubstr("iterations"));
}

TEST(PlanCommand, MrptParametersWithoutASectionAreRefusedBeforeAnythingRuns) {
  slamsweep::testing::TempDir dir;
  const auto config = slamsweep::testing::WriteFile(
      dir / "typo.yaml",
      "name: typo\nalgorithms:\n  - name: rbpf\n    adapter: mrpt-rbpf-slam\n    parameters: {sampleSize: 3}\n"
      "sequences:\n  - {catalog: simulated-floor, name: floor, max_scans: 40}\n");
  const auto plan = RunCli({"plan", config.string()});
  EXPECT_EQ(plan.exit_code, 2);
  EXPECT_THAT(plan.err, HasSubstr("algorithm 'rbpf'"));
  EXPECT_THAT(plan.err, HasSubstr("sampleSize"));
}

TEST(PlanCommand, AMissingRosterAlgorithmIsNamedWithItsInstallCommandAndNotBuiltOutsideTheBuildsOwnPrefix) {
  slamsweep::testing::TempDir dir;
  const auto config =
      slamsweep::testing::WriteFile(dir / "roster.yaml",
                                    "name: roster\nalgorithms:\n  - {name: gm, adapter: gmapping}\n"
                                    "sequences:\n  - {catalog: simulated-floor, name: floor, max_scans: 40}\n");
  // An empty roster prefix of the user's choosing: plan and run build only into the build's own prefix.
  std::filesystem::create_directories(dir / "prefix");
  ASSERT_EQ(setenv("SLAMSWEEP_SLAM_PREFIX", (dir / "prefix").c_str(), 1), 0);
  const auto plan = RunCli({"plan", config.string()});
  // The service loads sweeps without ever building (cli::LoadSweepText's default).
  std::string service_error;
  try {
    cli::LoadSweepText(evaluator::ReadTextFile(config), config.string(), {}, {});
  } catch (const evaluator::InputError& error) {
    service_error = error.what();
  }
  unsetenv("SLAMSWEEP_SLAM_PREFIX");
  EXPECT_EQ(plan.exit_code, 2);
  EXPECT_THAT(plan.err, HasSubstr("algorithm 'gm'"));
  EXPECT_THAT(plan.err, HasSubstr("scripts/install-slam.sh gmapping"));
  EXPECT_THAT(plan.err, ::testing::Not(HasSubstr("building gmapping now")));
  EXPECT_THAT(service_error, HasSubstr("scripts/install-slam.sh gmapping"));
  EXPECT_TRUE(std::filesystem::is_empty(dir / "prefix")) << "nothing installed into a prefix the build does not own";
}

/// A sweep of the odometry baseline and a command that fails, on a short simulated sequence.
std::filesystem::path SmallSweep(const slamsweep::testing::TempDir& dir, bool with_failing_program) {
  std::string text =
      "name: small\noutput: out\niterations: 2\nseed: 7\nworkers: 2\nevaluation: {stages: 4}\n"
      "algorithms:\n  - name: odometry\n    adapter: odometry\n";
  if (with_failing_program) {
    text +=
        "  - name: broken\n    adapter: command\n    timeout_s: 30\n    command:\n"
        "      argv: [/bin/false]\n      input_format: tum\n      trajectory: {path: traj.tum, format: tum}\n";
  }
  text +=
      "noise:\n  - name: noisy\n    odometry: {alpha1: 0.01, alpha3: 0.01}\n"
      "sequences:\n  - {catalog: simulated-floor, name: floor, max_scans: 40}\n";
  return slamsweep::testing::WriteFile(dir / "small.yaml", text);
}

TEST(RunCommand, WritesResultsJUnitAndReportAndSkipsFinishedRunsTheSecondTime) {
  ASSERT_TRUE(kWorkerProgramSet);
  slamsweep::testing::TempDir dir;
  const auto config = SmallSweep(dir, false);
  const auto first = RunCli({"run", config.string()});
  ASSERT_EQ(first.exit_code, 0) << first.out << first.err;
  EXPECT_THAT(first.out, HasSubstr("2 ok, 0 failed"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out/results.sqlite"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out/junit.xml"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out/report/index.html"));
  const nlohmann::json summary = ReadJson(dir / "out/summary.json");
  ASSERT_EQ(summary["runs"].size(), 2u);
  for (const auto& run : summary["runs"]) {
    EXPECT_EQ(run["status"], "ok");
    EXPECT_GT(run["metrics"]["ape_trans"]["rmse"].get<double>(), 0.0) << "noisy odometry has an error";
    EXPECT_TRUE(run["metrics"].contains("corners"));
  }
  const auto again = RunCli({"run", config.string(), "--no-report"});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_THAT(again.out, HasSubstr("0 ok, 0 failed, 2 done earlier"));
}

/// What Pillow (tests/cli/gif_frames.py, python3-pil) reads from a GIF; null with `why` when it cannot.
nlohmann::json ReadGifWithPillow(const std::filesystem::path& gif, std::string& why) {
  slamsweep::testing::TempDir dir;
  const std::string command = "/usr/bin/python3 '" + Repo("tests/cli/gif_frames.py") + "' '" + gif.string() + "' > '" +
                              (dir / "out.json").string() + "' 2> '" + (dir / "err.txt").string() + "'";
  if (std::system(command.c_str()) != 0) {
    why = "python3 with Pillow (apt-get install python3-pil) could not read " + gif.string() + ": " +
          evaluator::ReadTextFile(dir / "err.txt");
    return nullptr;
  }
  return ReadJson(dir / "out.json");
}

TEST(RunCommand, EveryRunPageOffersTheMapBeingBuiltAsAGifThatDecodes) {
  ASSERT_TRUE(kWorkerProgramSet);
  slamsweep::testing::TempDir dir;
  const auto run = RunCli({"run", SmallSweep(dir, false).string()});
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  std::size_t pages = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "out/report/runs")) {
    if (entry.path().extension() != ".html") continue;
    ++pages;
    const std::string page = evaluator::ReadTextFile(entry.path());
    // The worker's animation is played; its GIF is offered beside it.
    const std::filesystem::path folder = dir / "out/report/runs" / entry.path().stem();
    EXPECT_THAT(page, HasSubstr(entry.path().stem().string() + "/stages.png")) << entry.path();
    EXPECT_THAT(page, HasSubstr(entry.path().stem().string() + "/stages.gif")) << entry.path();
    ASSERT_TRUE(std::filesystem::is_regular_file(folder / "stages.gif")) << folder;
    EXPECT_LE(std::filesystem::file_size(folder / "stages.gif"), 2u << 20) << "the GIF cap";
    std::string why;
    const nlohmann::json gif = ReadGifWithPillow(folder / "stages.gif", why);
    if (gif.is_null()) SLAMSWEEP_SKIP_OR_FAIL_IN_CI(why);
    EXPECT_EQ(gif["format"], "GIF");
    EXPECT_EQ(gif["frames"], 4) << "one frame per stage (evaluation.stages: 4)";
    EXPECT_EQ(gif["loop"], 0) << "loops forever";
    EXPECT_LE(std::max(gif["width"].get<int>(), gif["height"].get<int>()), 480);
    // The finished map: occupied (0) and free (254) cells at its darkest and lightest.
    const std::vector<int> levels = gif["last_frame_levels"];
    ASSERT_FALSE(levels.empty());
    EXPECT_EQ(levels.front(), 0) << gif.dump();
    EXPECT_EQ(levels.back(), 254) << gif.dump();
  }
  EXPECT_EQ(pages, 2u);
  // Both runs share one sequence and cut: it was prepared once, in the sweep's cache of prepared inputs.
  std::size_t prepared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "out/prepared_inputs")) {
    prepared += entry.path().extension() == ".seq" ? 1 : 0;
  }
  EXPECT_EQ(prepared, 1u);
}

TEST(RunCommand, AFailingProgramIsRecordedAndTheSweepExitsOne) {
  slamsweep::testing::TempDir dir;
  const auto run = RunCli({"run", SmallSweep(dir, true).string(), "--no-report"});
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  EXPECT_THAT(run.out, HasSubstr("2 ok, 2 failed"));
  const nlohmann::json summary = ReadJson(dir / "out/summary.json");
  std::size_t failed = 0;
  for (const auto& entry : summary["runs"]) {
    if (entry["status"] == "failed") {
      ++failed;
      EXPECT_EQ(entry["algorithm"], "broken");
      EXPECT_EQ(entry["failure_kind"], "exit_code");
    }
  }
  EXPECT_EQ(failed, 2u);
  std::ifstream junit(dir / "out/junit.xml");
  std::stringstream xml;
  xml << junit.rdbuf();
  EXPECT_EQ(CountLines(xml.str(), "<failure"), 2u) << xml.str();
}

TEST(RunCommand, WarnsOncePerSequenceWhoseScansAreTooFarApartBeforeRunning) {
  ASSERT_TRUE(kWorkerProgramSet);
  slamsweep::testing::TempDir dir;
  slamsweep::testing::WriteFile(dir / "sparse.log", slamsweep::testing::SparseCarmenLog());
  // Two iterations under two noise settings on each sequence: four runs on the sparse log, one warning.
  const auto config = slamsweep::testing::WriteFile(
      dir / "density.yaml",
      "name: density\noutput: out\niterations: 2\nseed: 7\nworkers: 2\nevaluation: {stages: 2}\n"
      "algorithms:\n  - name: odometry\n    adapter: odometry\n"
      "noise:\n  - name: clean\n  - name: noisy\n    odometry: {alpha1: 0.01, alpha3: 0.01}\n"
      "sequences:\n  - {name: sparse, format: carmen, path: sparse.log, ground_truth: none}\n"
      "  - {catalog: simulated-floor, name: floor, max_scans: 40}\n");
  const auto run = RunCli({"run", config.string(), "--no-report"});
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_THAT(run.out, HasSubstr("8 ok, 0 failed"));
  EXPECT_EQ(CountLines(run.err, "warning: sequence 'sparse': scans too far apart for scan matching"), 1u) << run.err;
  EXPECT_THAT(run.err, HasSubstr("5.00 m apart at the median"));
  EXPECT_EQ(CountLines(run.err, "sequence 'floor'"), 0u) << run.err;
}

TEST(MergeCommand, ShardsMergedEqualTheWholeSweep) {
  slamsweep::testing::TempDir dir;
  const auto config = SmallSweep(dir, false);
  ASSERT_EQ(RunCli({"run", config.string(), "--no-report", "-o", (dir / "whole").string()}).exit_code, 0);
  ASSERT_EQ(RunCli({"run", config.string(), "--no-report", "--shard", "1/2", "-o", (dir / "s1").string()}).exit_code,
            0);
  ASSERT_EQ(RunCli({"run", config.string(), "--no-report", "--shard", "2/2", "-o", (dir / "s2").string()}).exit_code,
            0);
  const auto merged =
      RunCli({"merge", (dir / "s1").string(), (dir / "s2").string(), "-o", (dir / "merged").string(), "--no-report"});
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  auto by_id = [](const nlohmann::json& summary) {
    std::map<std::string, nlohmann::json> runs;
    for (const auto& run : summary["runs"]) runs[run["run_id"].get<std::string>()] = run["metrics"];
    return runs;
  };
  const auto whole = by_id(ReadJson(dir / "whole/summary.json"));
  const auto parts = by_id(ReadJson(dir / "merged/summary.json"));
  ASSERT_EQ(whole.size(), 2u);
  // The odometry baseline is deterministic: the same runs give the same metrics to the last bit.
  EXPECT_EQ(whole, parts);
}

}  // namespace
}  // namespace slamsweep
