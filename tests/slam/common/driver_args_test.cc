#include "slam/common/driver_args.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vector>

#include "evaluator/core/input_error.h"

namespace slamsweep::slam {
namespace {

using ::testing::HasSubstr;

DriverArgs Parse(std::vector<const char*> arguments) { return ParseDriverArgs(arguments); }

std::string ErrorOf(std::vector<const char*> arguments) {
  try {
    Parse(arguments);
  } catch (const evaluator::InputError& error) {
    return error.what();
  }
  return "no error";
}

TEST(DriverArgsTest, ReadsEveryPartOfTheContract) {
  const DriverArgs args = Parse({"--input", "in.log", "--output-dir", "out", "--seed", "18446744073709551615",
                                 "--stages", "4", "particles=30", "srr=0.1", "empty="});
  EXPECT_EQ(args.input, "in.log");
  EXPECT_EQ(args.output_dir, "out");
  ASSERT_TRUE(args.seed.has_value());
  EXPECT_EQ(*args.seed, 18446744073709551615ULL);
  EXPECT_EQ(args.stages, 4);
  EXPECT_EQ(args.parameters.at("particles"), "30");
  EXPECT_EQ(args.parameters.at("srr"), "0.1");
  EXPECT_EQ(args.parameters.at("empty"), "");
}

TEST(DriverArgsTest, DefaultsToTenStagesAndNoSeed) {
  const DriverArgs args = Parse({"--input", "a", "--output-dir", "b"});
  EXPECT_EQ(args.stages, 10);
  EXPECT_FALSE(args.seed.has_value());
  EXPECT_TRUE(args.parameters.empty());
}

TEST(DriverArgsTest, NamesWhatIsWrong) {
  EXPECT_THAT(ErrorOf({"--output-dir", "b"}), HasSubstr("--input FILE is required"));
  EXPECT_THAT(ErrorOf({"--input", "a"}), HasSubstr("--output-dir DIR is required"));
  EXPECT_THAT(ErrorOf({"--input"}), HasSubstr("--input: expected a value"));
  EXPECT_THAT(ErrorOf({"--input", "a", "--output-dir", "b", "--seed", "-3"}),
              HasSubstr("--seed: expected a non-negative integer, got '-3'"));
  EXPECT_THAT(ErrorOf({"--input", "a", "--output-dir", "b", "--verbose"}), HasSubstr("unknown option '--verbose'"));
  EXPECT_THAT(ErrorOf({"--input", "a", "--output-dir", "b", "particles"}),
              HasSubstr("'particles': expected a parameter as key=value"));
  EXPECT_THAT(ErrorOf({"--input", "a", "--output-dir", "b", "=3"}), HasSubstr("expected a parameter as key=value"));
  EXPECT_THAT(ErrorOf({"--input", "a", "--output-dir", "b", "k=1", "k=2"}), HasSubstr("parameter 'k' given twice"));
}

}  // namespace
}  // namespace slamsweep::slam
