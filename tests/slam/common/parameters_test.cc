#include "slam/common/parameters.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::slam {
namespace {

using ::testing::HasSubstr;

TEST(ParametersTest, GivenValuesOverrideDefaultsAndAreRecorded) {
  Parameters parameters({{"particles", "30"}, {"srr", "0.25"}, {"gui", "no"}, {"config", "tiny"}});
  EXPECT_EQ(parameters.Integer("particles", 10), 30);
  EXPECT_DOUBLE_EQ(parameters.Real("srr", 0.1), 0.25);
  EXPECT_FALSE(parameters.Flag("gui", true));
  EXPECT_EQ(parameters.Text("config", "viny"), "tiny");
  EXPECT_DOUBLE_EQ(parameters.Real("delta", 0.05), 0.05);
  EXPECT_NO_THROW(parameters.RejectUnread("gmapping"));
  EXPECT_EQ(parameters.Used().at("particles"), "30");
  EXPECT_EQ(parameters.Used().at("delta"), "0.05");
  EXPECT_EQ(parameters.Used().at("gui"), "false");
}

TEST(ParametersTest, RefusesAMisspeltNameListingTheAcceptedOnes) {
  Parameters parameters(std::map<std::string, std::string>{{"particels", "30"}});
  parameters.Integer("particles", 10);
  try {
    parameters.RejectUnread("gmapping");
    FAIL() << "no error";
  } catch (const evaluator::InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("unknown parameter(s) for gmapping: particels (accepted: particles)"));
  }
}

TEST(ParametersTest, RefusesValuesOfTheWrongType) {
  Parameters parameters({{"particles", "3.5"}, {"srr", "x"}, {"gui", "maybe"}});
  EXPECT_THROW(parameters.Integer("particles", 1), evaluator::InputError);
  EXPECT_THROW(parameters.Real("srr", 1.0), evaluator::InputError);
  EXPECT_THROW(parameters.Flag("gui", false), evaluator::InputError);
}

}  // namespace
}  // namespace slamsweep::slam
