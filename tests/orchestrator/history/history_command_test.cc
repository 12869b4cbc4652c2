#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/command.h"
#include "evaluator/core/input_error.h"
#include "orchestrator/history/history_store.h"
#include "orchestrator/history/regression.h"
#include "tests/orchestrator/history/synthetic_sweep.h"
#include "tests/support/shared_data.h"

namespace slamsweep::cli {

namespace {

using slamsweep::testing::TempDir;

struct CommandResult {
  int exit_code = 0;
  std::string out;
};

// Parses like RunCommandLine does for the history commands (errors propagate as exceptions).
CommandResult RunHistory(const std::vector<std::string>& args) {
  std::ostringstream out;
  std::ostringstream err;
  const Streams streams{out, err};
  CLI::App app{"slamsweep", "slamsweep"};
  app.require_subcommand(1);
  int exit_code = 0;
  RegisterHistoryCommands(app, streams, exit_code);
  std::vector<const char*> argv = {"slamsweep", "history"};
  for (const std::string& arg : args) argv.push_back(arg.c_str());
  app.parse(static_cast<int>(argv.size()), argv.data());
  return {exit_code, out.str()};
}

class HistoryCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    orchestrator::testing::SyntheticSweep night;
    orchestrator::testing::WriteSyntheticSweep(dir_ / "night1", night);
    night.seed = 2;
    night.started_at = "2026-11-21T02:00:00Z";
    orchestrator::testing::WriteSyntheticSweep(dir_ / "rerun", night);
    night.seed = 3;
    night.odometry_sigma *= 2.0;
    night.started_at = "2026-11-22T02:00:00Z";
    orchestrator::testing::WriteSyntheticSweep(dir_ / "noisier", night);
  }
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }
  TempDir dir_;
};

TEST_F(HistoryCommandTest, RecordTwiceIsANoOp) {
  const CommandResult first = RunHistory({"record", Path("night1"), "--history", Path("h.sqlite")});
  EXPECT_EQ(first.exit_code, 0);
  EXPECT_NE(first.out.find("recorded night '2026-11-20T02:00:00Z'"), std::string::npos) << first.out;
  const CommandResult second = RunHistory({"record", Path("night1"), "--history", Path("h.sqlite")});
  EXPECT_NE(second.out.find("already recorded"), std::string::npos) << second.out;
  EXPECT_EQ(orchestrator::HistoryStore::OpenExisting(dir_ / "h.sqlite").Nights().size(), 1u);
}

TEST_F(HistoryCommandTest, CompareExitsThreeOnARegressionOnly) {
  RunHistory({"record", Path("night1"), "--history", Path("h.sqlite"), "--label", "base"});
  // A re-run of the same setting: exit 0.
  const CommandResult rerun = RunHistory({"compare", Path("rerun"), "--previous", "--history", Path("h.sqlite")});
  EXPECT_EQ(rerun.exit_code, 0) << rerun.out;
  EXPECT_NE(rerun.out.find("0 regressions"), std::string::npos) << rerun.out;
  // Each series names its odometry mode: two modes of one cell never print as the same row.
  EXPECT_NE(rerun.out.find("/recorded ape_trans.rmse"), std::string::npos) << rerun.out;
  RunHistory({"record", Path("rerun"), "--history", Path("h.sqlite")});

  // Noisier odometry against a named baseline: exit 3, JSON and JUnit say so.
  const CommandResult noisier = RunHistory({"compare", Path("noisier"), "--baseline-label", "base", "--history",
                                            Path("h.sqlite"), "--json", "--junit", Path("regressions.xml")});
  EXPECT_EQ(noisier.exit_code, orchestrator::kRegressionExitCode);
  EXPECT_EQ(noisier.exit_code, 3);
  const nlohmann::json json = nlohmann::json::parse(noisier.out);
  EXPECT_EQ(json["baseline"], "base");
  EXPECT_EQ(json["counts"]["regression"], 1);
  std::ifstream junit(dir_ / "regressions.xml");
  std::stringstream xml;
  xml << junit.rdbuf();
  EXPECT_NE(xml.str().find("<failure type=\"regression\""), std::string::npos);

  // --previous after recording "rerun": the baseline is "rerun", still a regression.
  const CommandResult previous =
      RunHistory({"compare", Path("noisier"), "--previous", "--history", Path("h.sqlite"), "--json"});
  EXPECT_EQ(previous.exit_code, 3);
  EXPECT_EQ(nlohmann::json::parse(previous.out)["baseline"], "2026-11-21T02:00:00Z");
  // Once recorded, --previous still means the night before it, not itself.
  RunHistory({"record", Path("noisier"), "--history", Path("h.sqlite")});
  const CommandResult recorded =
      RunHistory({"compare", Path("noisier"), "--previous", "--history", Path("h.sqlite"), "--json"});
  EXPECT_EQ(nlohmann::json::parse(recorded.out)["baseline"], "2026-11-21T02:00:00Z");
}

TEST_F(HistoryCommandTest, ConfigRegressionBlockSetsTheTest) {
  RunHistory({"record", Path("night1"), "--history", Path("h.sqlite"), "--label", "base"});
  // The smallest two-sided p of 10 + 10 samples is 2 / C(20, 10) ~ 1.1e-5, so alpha 1e-6 never flags anything.
  const std::string config = slamsweep::testing::WriteFile(dir_ / "sweep.yaml", R"(name: nightly
algorithms: [{name: icp-slam, adapter: odometry}]
sequences:
  - {name: floor, format: simulated, ground_truth: exact, simulation: {floor_plan: {seed: 3}}}
regression: {alpha: 0.000001, min_effect: 0.2}
)")
                                 .string();
  const std::vector<std::string> compare = {"compare",        Path("noisier"), "--baseline-label", "base", "--history",
                                            Path("h.sqlite"), "--json",        "--config",         config};
  const CommandResult strict = RunHistory(compare);
  EXPECT_EQ(strict.exit_code, 0) << strict.out;
  EXPECT_DOUBLE_EQ(nlohmann::json::parse(strict.out)["alpha"].get<double>(), 1e-6);
  // An explicit option wins over the config.
  std::vector<std::string> with_alpha = compare;
  with_alpha.insert(with_alpha.end(), {"--alpha", "0.05"});
  EXPECT_EQ(RunHistory(with_alpha).exit_code, 3);
  slamsweep::testing::WriteFile(dir_ / "bad.yaml", "name: nightly\nregression: {alpha: 2}\n");
  std::vector<std::string> bad = compare;
  bad.back() = Path("bad.yaml");
  EXPECT_THROW(RunHistory(bad), evaluator::InputError);
}

TEST_F(HistoryCommandTest, BadUsageIsAnError) {
  RunHistory({"record", Path("night1"), "--history", Path("h.sqlite"), "--label", "base"});
  // Neither or both of --previous / --baseline-label.
  EXPECT_THROW(RunHistory({"compare", Path("rerun"), "--history", Path("h.sqlite")}), evaluator::InputError);
  EXPECT_THROW(
      RunHistory({"compare", Path("rerun"), "--previous", "--baseline-label", "base", "--history", Path("h.sqlite")}),
      CLI::ParseError);
  EXPECT_THROW(RunHistory({"compare", Path("rerun"), "--baseline-label", "nope", "--history", Path("h.sqlite")}),
               evaluator::InputError);
  EXPECT_THROW(RunHistory({"compare", Path("rerun"), "--previous", "--history", Path("missing.sqlite")}),
               evaluator::InputError);
  EXPECT_THROW(RunHistory({"compare", Path("rerun"), "--previous", "--history", Path("h.sqlite"), "--alpha", "2"}),
               evaluator::InputError);
  // --previous with only the current night recorded: nothing before it.
  EXPECT_THROW(RunHistory({"compare", Path("night1"), "--previous", "--history", Path("h.sqlite")}),
               evaluator::InputError);
  EXPECT_THROW(RunHistory({"record", Path("missing"), "--history", Path("h.sqlite")}), evaluator::InputError);
}

}  // namespace
}  // namespace slamsweep::cli
