// The slam_toolbox driver's scan filter against the rule read in slam_toolbox's node (shouldProcessScan): the
// expected answers are worked out by hand from that rule for the offline file's values (minimum travel 0.5 m,
// so a scan passes from 0.8 * 0.25 m^2 = 0.2 m^2, about 0.447 m; minimum time 0.5 s).
#include "slam/slam_toolbox/node_scan_filter.h"

#include <gtest/gtest.h>

#include <vector>

namespace slamsweep::slam::slam_toolbox_driver {
namespace {

TEST(NodeScanFilterTest, TheFirstScanPassesAndTheNextThreeNeverDo) {
  NodeScanFilter filter(0.5, 0.5, 1);
  EXPECT_TRUE(filter.Pass(0.0, 0.0, 0.0));
  // Far and late enough, but the node counts four scans before it hands another over.
  EXPECT_FALSE(filter.Pass(10.0, 5.0, 0.0));
  EXPECT_FALSE(filter.Pass(20.0, 10.0, 0.0));
  EXPECT_FALSE(filter.Pass(30.0, 15.0, 0.0));
  EXPECT_TRUE(filter.Pass(40.0, 20.0, 0.0));  // the fifth
}

TEST(NodeScanFilterTest, AScanPassesFromEightyPercentOfTheSquaredTravelOn) {
  NodeScanFilter filter(0.5, 0.5, 1);
  ASSERT_TRUE(filter.Pass(0.0, 0.0, 0.0));
  for (double t : {1.0, 2.0, 3.0}) ASSERT_FALSE(filter.Pass(t, 0.0, 0.0));
  EXPECT_FALSE(filter.Pass(4.0, 0.44, 0.0));  // 0.1936 m^2 < 0.2 m^2
  EXPECT_FALSE(filter.Pass(5.0, 0.3, 0.33));  // 0.1989 m^2
  EXPECT_TRUE(filter.Pass(6.0, 0.3, 0.34));   // 0.2056 m^2
  // The reference is now the scan that passed: the same place again does not pass.
  EXPECT_FALSE(filter.Pass(7.0, 0.3, 0.34));
  EXPECT_TRUE(filter.Pass(8.0, 0.3, 0.80));
}

TEST(NodeScanFilterTest, TooSoonAfterTheLastScanThatPassedIsRejected) {
  NodeScanFilter filter(0.5, 0.5, 1);
  ASSERT_TRUE(filter.Pass(100.0, 0.0, 0.0));
  for (int i = 0; i < 3; ++i) ASSERT_FALSE(filter.Pass(100.1, 0.0, 0.0));
  EXPECT_FALSE(filter.Pass(100.4, 2.0, 0.0));  // 0.4 s after the last that passed
  EXPECT_TRUE(filter.Pass(100.5, 2.0, 0.0));   // 0.5 s: not less than the interval
}

TEST(NodeScanFilterTest, TurningOnTheSpotNeverPasses) {
  // The node tests the distance only (Karto's Mapper tests the heading after it).
  NodeScanFilter filter(0.5, 0.5, 1);
  ASSERT_TRUE(filter.Pass(0.0, 1.0, 1.0));
  for (int i = 1; i < 50; ++i) EXPECT_FALSE(filter.Pass(i, 1.0, 1.0)) << i;
}

TEST(NodeScanFilterTest, ThrottlingKeepsEveryNthScanByTheCountOfAllScans) {
  NodeScanFilter filter(0.5, 0.0, 3);
  ASSERT_TRUE(filter.Pass(0.0, 0.0, 0.0));  // scan 1
  std::vector<int> passed;
  for (int scan = 2; scan <= 12; ++scan) {
    if (filter.Pass(scan, scan * 1.0, 0.0)) passed.push_back(scan);
  }
  // Scans 3 and 6 and 9 and 12 are multiples of 3; 3 is among the first four.
  EXPECT_EQ(passed, (std::vector<int>{6, 9, 12}));
}

}  // namespace
}  // namespace slamsweep::slam::slam_toolbox_driver
