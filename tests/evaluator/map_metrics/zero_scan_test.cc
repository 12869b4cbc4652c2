#include "evaluator/map_metrics/zero_scan.h"

#include <gtest/gtest.h>

#include <vector>

namespace slamsweep::evaluator {
namespace {

TEST(ZeroScanTest, RunsMaxAndZeroTests) {
  std::vector<float> row(70, 0.0f);
  row[0] = 1.0f;                                 // run [0, 1)
  for (int c = 30; c < 34; ++c) row[c] = -2.5f;  // run [30, 34) across a block edge
  row[63] = 0.5f;                                // run [63, 65)
  row[64] = 3.0f;
  row[69] = -0.0f;  // negative zero is zero
  RowRuns runs(70, 1);
  AppendNonZeroRuns(row.data(), 70, runs);
  ASSERT_EQ(runs.run_count(), 3);
  EXPECT_EQ(runs.begin_col(0), 0);
  EXPECT_EQ(runs.end_col(0), 1);
  EXPECT_EQ(runs.begin_col(1), 30);
  EXPECT_EQ(runs.end_col(1), 34);
  EXPECT_EQ(runs.begin_col(2), 63);
  EXPECT_EQ(runs.end_col(2), 65);
  EXPECT_EQ(MaxAbs(row.data(), row.size()), 3.0f);
  EXPECT_FALSE(AllZero(row.data(), 70));
  EXPECT_TRUE(AllZero(row.data() + 34, 29));
  EXPECT_TRUE(AllZero(row.data() + 65, 5));

  std::vector<float> full(40, 1.0f);  // one run to the end of the row
  RowRuns one(40, 1);
  AppendNonZeroRuns(full.data(), 40, one);
  ASSERT_EQ(one.run_count(), 1);
  EXPECT_EQ(one.end_col(0), 40);
}

}  // namespace
}  // namespace slamsweep::evaluator
