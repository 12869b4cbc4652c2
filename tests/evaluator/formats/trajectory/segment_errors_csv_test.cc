#include "evaluator/formats/trajectory/segment_errors_csv.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(SegmentErrorsCsvTest, RoundTripsEveryNumberExactly) {
  const std::vector<SegmentErrorRecord> records = {{10, 100.25, 131.5, 0.1 + 0.2, 3.0000000000000004, 1e-7},
                                                   {20, 0, 1e9, 0, 0, 0}};
  std::ostringstream out;
  WriteSegmentErrorsCsv(records, out);
  EXPECT_THAT(out.str(),
              ::testing::StartsWith(std::string(kSegmentErrorsHeader) + "\n10,100.25,131.5,0.30000000000000004,"));
  const std::vector<SegmentErrorRecord> read = ParseSegmentErrorsCsv(out.str(), "rpe_segments.csv");
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0].translation_m, 0.1 + 0.2);
  EXPECT_EQ(read[0].translation_pct, 3.0000000000000004);
  EXPECT_EQ(read[0].rotation_deg_per_m, 1e-7);
  EXPECT_EQ(read[1].end_s, 1e9);
}

TEST(SegmentErrorsCsvTest, AHeaderAloneIsNoSegments) {
  EXPECT_TRUE(ParseSegmentErrorsCsv(std::string(kSegmentErrorsHeader) + "\n", "x.csv").empty());
}

TEST(SegmentErrorsCsvTest, BadInputNamesFileAndLine) {
  EXPECT_THAT([] { ParseSegmentErrorsCsv("", "x.csv"); },
              ThrowsMessage<InputError>(HasSubstr("x.csv: expected the header")));
  EXPECT_THAT([] { ParseSegmentErrorsCsv("a,b\n", "x.csv"); }, ThrowsMessage<InputError>(HasSubstr("x.csv:1")));
  const std::string header(kSegmentErrorsHeader);
  EXPECT_THAT([&] { ParseSegmentErrorsCsv(header + "\n1,2,3\n", "x.csv"); },
              ThrowsMessage<InputError>(HasSubstr("x.csv:2: expected 6 fields")));
  EXPECT_THAT([&] { ParseSegmentErrorsCsv(header + "\n1,2,3,4,nan,6\n", "x.csv"); },
              ThrowsMessage<InputError>(HasSubstr("translation_pct")));
}

}  // namespace
}  // namespace slamsweep::evaluator
