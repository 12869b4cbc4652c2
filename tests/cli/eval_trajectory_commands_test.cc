#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli/run_cli.h"
#include "tests/support/shared_data.h"

namespace slamsweep {
namespace {

using ::testing::HasSubstr;
using testing::RunCli;

nlohmann::json ExpectedEvoCase(const std::string& name) {
  std::ifstream in(testing::SharedRoot() / "reference/trajectories/expected_evo.json");
  const nlohmann::json all = nlohmann::json::parse(in);
  for (const auto& c : all.at("cases")) {
    if (c.at("name") == name) return c.at("expected");
  }
  throw std::runtime_error("no case " + name);
}

TEST(EvalApeCommandTest, JsonMatchesEvoOnIntelGmapping) {
  SLAMSWEEP_REQUIRE_SHARED(dir, "reference/trajectories/expected_evo.json");
  const auto run = RunCli({"eval", "ape", (dir.parent_path() / "intel_corrected.tum").string(),
                           (dir.parent_path() / "intel_gmapping.tum").string(), "--align", "se3", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json result = nlohmann::json::parse(run.out);
  const nlohmann::json expected = ExpectedEvoCase("intel_gmapping_ape_se3");
  for (const char* key : {"rmse", "mean", "median", "std", "min", "max", "sse"}) {
    EXPECT_NEAR(result.at(key).get<double>(), expected.at(key).get<double>(), 1e-6 * expected.at(key).get<double>())
        << key;
  }
  EXPECT_EQ(result.at("n"), expected.at("n"));
  EXPECT_TRUE(result.contains("specification"));
}

TEST(EvalRpeCommandTest, JsonMatchesEvoForOneMetreDelta) {
  SLAMSWEEP_REQUIRE_SHARED(dir, "reference/trajectories/expected_evo.json");
  const auto run =
      RunCli({"eval", "rpe", (dir.parent_path() / "intel_corrected.tum").string(),
              (dir.parent_path() / "intel_gmapping.tum").string(), "--delta", "1", "--delta-unit", "m", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json result = nlohmann::json::parse(run.out);
  const nlohmann::json expected = ExpectedEvoCase("intel_gmapping_rpe_1m");
  EXPECT_NEAR(result.at("rmse").get<double>(), expected.at("rmse").get<double>(),
              1e-6 * expected.at("rmse").get<double>());
  EXPECT_EQ(result.at("n"), expected.at("n"));
}

TEST(EvalApeCommandTest, TableOutputNamesTheStatistics) {
  SLAMSWEEP_REQUIRE_SHARED(gt, "reference/trajectories/synth_gt.tum");
  const auto run = RunCli({"eval", "ape", gt.string(), gt.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("rmse"));
  EXPECT_THAT(run.out, HasSubstr("median"));
}

TEST(EvalApeCommandTest, MissingFileExitsTwoNamingTheFile) {
  const auto run = RunCli({"eval", "ape", "/nonexistent/ref.tum", "/nonexistent/est.tum"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("/nonexistent/ref.tum"));
}

TEST(EvalApeCommandTest, ZeroAssociationsExitsTwoNamingBothTimeRanges) {
  testing::TempDir dir;
  testing::WriteFile(dir / "ref.tum", "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n");
  testing::WriteFile(dir / "est.tum", "100 0 0 0 0 0 0 1\n101 1 0 0 0 0 0 1\n");
  const auto run = RunCli({"eval", "ape", (dir / "ref.tum").string(), (dir / "est.tum").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("0.000000"));
  EXPECT_THAT(run.err, HasSubstr("100.000000"));
}

TEST(EvalApeCommandTest, BadOptionValuesExitTwo) {
  SLAMSWEEP_REQUIRE_SHARED(gt, "reference/trajectories/synth_gt.tum");
  EXPECT_EQ(RunCli({"eval", "ape", gt.string(), gt.string(), "--align", "banana"}).exit_code, 2);
  EXPECT_EQ(RunCli({"eval", "ape", gt.string(), gt.string(), "--pose-relation", "full"}).exit_code, 2);
  EXPECT_EQ(RunCli({"eval", "ape", gt.string()}).exit_code, 2);
  EXPECT_EQ(RunCli({"eval", "rpe", gt.string(), gt.string(), "--delta", "1", "--delta-unit", "parsecs"}).exit_code, 2);
  EXPECT_EQ(RunCli({"eval", "rpe", gt.string(), gt.string(), "--delta", "x", "--delta-unit", "m"}).exit_code, 2);
}

TEST(EvalApeCommandTest, TruncatedLineExitsTwoWithFileAndLine) {
  testing::TempDir dir;
  testing::WriteFile(dir / "ref.tum", "0 0 0 0 0 0 0 1\n1 1 0 0 0 0\n");
  const auto run = RunCli({"eval", "ape", (dir / "ref.tum").string(), (dir / "ref.tum").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("ref.tum:2"));
}

TEST(EvalRelationsCommandTest, ExactTrajectoryGivesZeroError) {
  // Relations measured on the trajectory itself must score zero on it.
  testing::TempDir dir;
  testing::WriteFile(dir / "traj.tum",
                     "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0.7071067811865476 0.7071067811865476\n2 1 1 0 0 0 "
                     "0.7071067811865476 0.7071067811865476\n");
  // Pose at t=2 in the frame of the pose at t=1: 1 m ahead (+x of a frame facing +y), no turn.
  testing::WriteFile(dir / "rel.relations", "1 2 1 0 0 0 0 0\n");
  const auto run =
      RunCli({"eval", "relations", (dir / "traj.tum").string(), (dir / "rel.relations").string(), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json result = nlohmann::json::parse(run.out);
  EXPECT_EQ(result.at("used"), 1);
  EXPECT_EQ(result.at("not_covered"), 0);
  EXPECT_NEAR(result.at("translation_abs_mean_m").get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(result.at("rotation_abs_mean_deg").get<double>(), 0.0, 1e-7);
}

TEST(EvalRelationsCommandTest, KnownOffsetGivesKnownError) {
  // Claim the second pose is 1.5 m ahead while the trajectory says 1 m: 0.5 m error.
  testing::TempDir dir;
  testing::WriteFile(dir / "traj.tum", "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n");
  testing::WriteFile(dir / "rel.relations", "0 1 1.5 0 0 0 0 0\n5 6 1 0 0 0 0 0\n");
  const auto run =
      RunCli({"eval", "relations", (dir / "traj.tum").string(), (dir / "rel.relations").string(), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json result = nlohmann::json::parse(run.out);
  EXPECT_EQ(result.at("used"), 1);
  EXPECT_EQ(result.at("not_covered"), 1);  // the relation at t = 5..6 s lies outside the trajectory
  EXPECT_NEAR(result.at("translation_abs_mean_m").get<double>(), 0.5, 1e-9);
  EXPECT_NEAR(result.at("translation_sq_mean_m2").get<double>(), 0.25, 1e-9);
}

}  // namespace
}  // namespace slamsweep
