#include "orchestrator/matrix/plan_listing.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

#include "orchestrator/matrix/expand_matrix.h"
#include "tests/orchestrator/matrix/test_config.h"
#include "orchestrator/run/run_json.h"

namespace slamsweep::orchestrator {
namespace {

using ::testing::HasSubstr;

TEST(PlanListingTest, FormatsParametersAsSortedKeyValuePairs) {
  EXPECT_EQ(FormatParameters(nlohmann::json::object()), "-");
  EXPECT_EQ(FormatParameters({{"b", "fast"}, {"a", 40}, {"c", true}, {"d", 0.5}}), "a=40;b=fast;c=true;d=0.5");
}

TEST(PlanListingTest, OneLinePerRunThenTheCount) {
  SweepConfig config = testing::TwoByTwo();
  config.algorithms.pop_back();
  config.iterations = 1;
  config.sequences.pop_back();
  config.noise.pop_back();
  const std::vector<RunSpec> runs = ExpandMatrix(config);
  const std::string text = FormatPlan(runs);
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 1 + runs.size() + 1);  // header, runs, count
  EXPECT_THAT(lines[0], HasSubstr("run_id"));
  EXPECT_THAT(lines[0], HasSubstr("seed"));
  EXPECT_THAT(lines[1], ::testing::StartsWith(runs[0].run_id + "  "));
  EXPECT_THAT(lines[1], HasSubstr(" icp "));
  EXPECT_THAT(lines[1], HasSubstr(" p=1;q=a "));
  EXPECT_THAT(lines[1], HasSubstr(" seq1 "));
  EXPECT_THAT(lines[1], HasSubstr(" clean "));
  EXPECT_THAT(lines[1], ::testing::EndsWith(" " + std::to_string(runs[0].seed)));
  EXPECT_EQ(lines.back(), "4 runs");
}

TEST(PlanListingTest, JsonIsAnArrayOfRunJsonObjects) {
  const std::vector<RunSpec> runs = ExpandMatrix(testing::TwoByTwo());
  const nlohmann::json plan = PlanJson(runs);
  ASSERT_TRUE(plan.is_array());
  ASSERT_EQ(plan.size(), runs.size());
  EXPECT_EQ(plan[5]["run_id"], runs[5].run_id);
  EXPECT_EQ(RunSpecFromJson(plan[5]).run_id, runs[5].run_id);
  EXPECT_EQ(FormatPlan({}), "run_id  algorithm  parameters  sequence  noise  iteration  seed\n0 runs\n");
}

}  // namespace
}  // namespace slamsweep::orchestrator
