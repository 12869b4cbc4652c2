#include "orchestrator/run/run_flags.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

TEST(RunFlagsTest, EveryFlagHasItsOwnNameLabelAndMeaningAndReadsBackFromItsName) {
  std::set<std::string_view> names;
  for (RunFlag flag : kAllRunFlags) {
    EXPECT_TRUE(names.insert(RunFlagName(flag)).second) << RunFlagName(flag);
    EXPECT_EQ(RunFlagFromName(RunFlagName(flag)), flag);
    EXPECT_FALSE(RunFlagLabel(flag).empty());
    EXPECT_FALSE(RunFlagMeaning(flag).empty());
  }
  EXPECT_EQ(RunFlagFromName("best"), std::nullopt);
}

TEST(RunFlagsTest, JsonAndTextRoundTripInOneOrder) {
  RunFlags flags;
  EXPECT_TRUE(flags.empty());
  EXPECT_FALSE(flags.ExcludedFromBest());
  flags.Set(RunFlag::kUnisolated);
  flags.Set(RunFlag::kOdometryIsReference);
  EXPECT_TRUE(flags.ExcludedFromBest());
  EXPECT_EQ(ToJson(flags), json::parse(R"(["odometry_is_reference", "unisolated"])"));
  EXPECT_EQ(RunFlagsText(flags), "odometry_is_reference;unisolated");
  EXPECT_EQ(RunFlagsLabel(flags), "odometry = reference, unisolated");
  EXPECT_EQ(RunFlagsFromJson(ToJson(flags)), flags);
  EXPECT_EQ(RunFlagsFromText(RunFlagsText(flags)), flags);
  EXPECT_TRUE(RunFlagsFromText("").empty());
  EXPECT_TRUE(RunFlagsFromJson(nullptr).empty());
  flags.Set(RunFlag::kUnisolated, false);
  EXPECT_EQ(flags, RunFlags{RunFlag::kOdometryIsReference});
}

TEST(RunFlagsTest, UnknownOrMistypedFlagsAreErrorsNamingWhere) {
  try {
    RunFlagsFromJson(json::parse(R"(["stale", "shiny"])"), "result.json: flags");
    FAIL() << "no error";
  } catch (const evaluator::InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("result.json: flags[1]"));
    EXPECT_THAT(error.what(), HasSubstr("shiny"));
  }
  EXPECT_THROW(RunFlagsFromJson(json("stale")), evaluator::InputError);
  EXPECT_THROW(RunFlagsFromJson(json::parse("[1]")), evaluator::InputError);
  EXPECT_THROW(RunFlagsFromText("stale;;", "runs.flags"), evaluator::InputError);
}

TEST(RunFlagsTest, ARunsFlagsJoinItsResultFlagsWithTheOdometryBooleans) {
  const json planned_reference = {{"odometry_is_reference", true}};
  // Measured by the worker: its value wins over the plan.
  EXPECT_EQ(RunFlagsOf(planned_reference, json{{"odometry_is_reference", false}}), RunFlags{});
  EXPECT_EQ(RunFlagsOf(planned_reference, nullptr), RunFlags{RunFlag::kOdometryIsReference});
  // A result recorded before the flags field existed.
  EXPECT_EQ(RunFlagsOf(json::object(), json{{"odometry_is_reference", true}}), RunFlags{RunFlag::kOdometryIsReference});
  EXPECT_EQ(RunFlagsOf(json::object(), json{{"flags", {"stale", "unisolated"}}}),
            (RunFlags{RunFlag::kStale, RunFlag::kUnisolated}));
  EXPECT_THROW(RunFlagsOf(json::object(), json{{"flags", {"stale", 3}}}), evaluator::InputError);
}

}  // namespace
}  // namespace slamsweep::orchestrator
