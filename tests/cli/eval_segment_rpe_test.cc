// `slamsweep eval rpe --segments`: the segment RPE from the command line, checked against the same
// command run per length with evo's options (--delta L --delta-unit m --all-pairs --pairs-from-reference).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/run_cli.h"
#include "tests/support/shared_data.h"

namespace slamsweep {
namespace {

using ::testing::HasSubstr;
using testing::RunCli;

TEST(EvalSegmentRpeCommandTest, EachLengthEqualsRpeAtThatDeltaFromTheReference) {
  SLAMSWEEP_REQUIRE_SHARED(reference, "reference/trajectories/intel_corrected.tum");
  SLAMSWEEP_REQUIRE_SHARED(estimate, "reference/trajectories/intel_gmapping.tum");
  const auto run = RunCli({"eval", "rpe", reference.string(), estimate.string(), "--segments", "20,5,10", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json result = nlohmann::json::parse(run.out);
  ASSERT_EQ(result.at("lengths").size(), 3u);
  EXPECT_EQ(result.at("specification").at("lengths_from"), "--segments");
  double previous = 0.0;
  for (const nlohmann::json& length : result.at("lengths")) {
    const double d = length.at("length_m").get<double>();
    EXPECT_GT(d, previous);  // ascending
    previous = d;
    for (const auto& [relation, key] :
         {std::pair<const char*, const char*>{"trans", "translation_m"}, {"rot-deg", "rotation_deg_per_m"}}) {
      const auto per_delta =
          RunCli({"eval", "rpe", reference.string(), estimate.string(), "--delta", std::to_string(d), "--delta-unit",
                  "m", "--all-pairs", "--pairs-from-reference", "--pose-relation", relation, "--json"});
      ASSERT_EQ(per_delta.exit_code, 0) << per_delta.err;
      const nlohmann::json rpe = nlohmann::json::parse(per_delta.out);
      EXPECT_EQ(rpe.at("specification").at("pairs_from"), "reference");
      EXPECT_EQ(length.at("n"), rpe.at("n")) << d;
      const double scale = std::string(relation) == "trans" ? 1.0 : d;  // deg per metre of segment
      EXPECT_NEAR(length.at(key).at("mean").get<double>() * scale, rpe.at("mean").get<double>(), 1e-12) << d;
      EXPECT_NEAR(length.at(key).at("max").get<double>() * scale, rpe.at("max").get<double>(), 1e-12) << d;
    }
    EXPECT_NEAR(length.at("translation_pct").at("mean").get<double>(),
                100.0 * length.at("translation_m").at("mean").get<double>() / d, 1e-9);
  }
}

TEST(EvalSegmentRpeCommandTest, AutoTakesTenToFiftyPercentOfTheReferencePath) {
  SLAMSWEEP_REQUIRE_SHARED(reference, "reference/trajectories/intel_corrected.tum");
  SLAMSWEEP_REQUIRE_SHARED(estimate, "reference/trajectories/intel_gmapping.tum");
  const auto run = RunCli({"eval", "rpe", reference.string(), estimate.string(), "--segments", "auto", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json result = nlohmann::json::parse(run.out);
  const double path = result.at("specification").at("reference_path_m").get<double>();
  ASSERT_EQ(result.at("lengths").size(), 5u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(result.at("lengths")[k].at("length_m").get<double>(), std::round(0.1 * (k + 1) * path));
  }
  const auto table = RunCli({"eval", "rpe", reference.string(), estimate.string(), "--segments", "auto"});
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_THAT(table.out, HasSubstr("deg/m"));
  EXPECT_THAT(table.out, HasSubstr(" %"));
}

TEST(EvalSegmentRpeCommandTest, BadSegmentOptionsExitTwo) {
  SLAMSWEEP_REQUIRE_SHARED(gt, "reference/trajectories/synth_gt.tum");
  const std::string g = gt.string();
  const auto bad_list = RunCli({"eval", "rpe", g, g, "--segments", "5,x"});
  EXPECT_EQ(bad_list.exit_code, 2);
  EXPECT_THAT(bad_list.err, HasSubstr("--segments"));
  EXPECT_EQ(RunCli({"eval", "rpe", g, g, "--segments", "5,5"}).exit_code, 2);
  EXPECT_EQ(RunCli({"eval", "rpe", g, g, "--segments", "-5"}).exit_code, 2);
  EXPECT_EQ(RunCli({"eval", "rpe", g, g, "--segments", "5", "--delta", "1"}).exit_code, 2);
  EXPECT_EQ(RunCli({"eval", "rpe", g, g, "--segments", "5", "--align", "se2"}).exit_code, 2);
  const auto no_delta = RunCli({"eval", "rpe", g, g});
  EXPECT_EQ(no_delta.exit_code, 2);
  EXPECT_THAT(no_delta.err, HasSubstr("--delta"));
}

}  // namespace
}  // namespace slamsweep
