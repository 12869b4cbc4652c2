// The spacing of consecutive scans on hand-made sequences; every expected percentile is worked out by hand
// in the comments (rank (n - 1) * p of the sorted steps, interpolated).
#include "evaluator/sequence/scan_spacing.h"

#include <gtest/gtest.h>

#include <numbers>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

struct Step {
  double stamp_s;
  double x_m;
  double y_m;
  double yaw_rad;
};

Sequence Made(const std::vector<Step>& steps) {
  Sequence sequence;
  sequence.name = "made";
  for (const Step& step : steps) {
    LaserScan scan;
    scan.stamp_s = step.stamp_s;
    scan.ranges_m = {1.0f, 2.0f};
    scan.angle_increment_rad = 0.1;
    scan.range_max_m = 10.0;
    sequence.scans.push_back(scan);
    sequence.odometry.Add(step.stamp_s, Pose::Planar(step.x_m, step.y_m, step.yaw_rad));
  }
  return sequence;
}

TEST(ScanSpacingTest, PercentilesOfAHandMadeSequence) {
  // Gaps 1, 2, 0.5, 2, 4.5 s; sorted 0.5 1 2 2 4.5: median (rank 2) 2; p95 (rank 3.8) 2 + 0.8 * 2.5 = 4.
  // Travel 5 (3-4-5), 0, 1, 2, 0.5 m; sorted 0 0.5 1 2 5: median 1; p95 2 + 0.8 * 3 = 4.4.
  // Rotation 0.1, 0.3, 0, 0.6 and 3.2 rad taken the short way, 2 pi - 3.2; sorted 0 0.1 0.3 0.6 (2 pi - 3.2):
  // median 0.3; p95 0.6 + 0.8 * (2 pi - 3.8).
  const Sequence sequence = Made({{0.0, 0.0, 0.0, 0.0},
                                  {1.0, 3.0, 4.0, 0.1},
                                  {3.0, 3.0, 4.0, 0.4},
                                  {3.5, 4.0, 4.0, 0.4},
                                  {5.5, 4.0, 6.0, -0.2},
                                  {10.0, 4.3, 6.4, 3.0}});
  const std::optional<ScanSpacing> spacing = ComputeScanSpacing(sequence);
  ASSERT_TRUE(spacing);
  EXPECT_EQ(spacing->steps, 5u);
  EXPECT_NEAR(spacing->gap_s.median, 2.0, 1e-12);
  EXPECT_NEAR(spacing->gap_s.p95, 4.0, 1e-12);
  EXPECT_NEAR(spacing->travel_m.median, 1.0, 1e-12);
  EXPECT_NEAR(spacing->travel_m.p95, 4.4, 1e-12);
  EXPECT_NEAR(spacing->rotation_rad.median, 0.3, 1e-9);
  EXPECT_NEAR(spacing->rotation_rad.p95, 0.6 + 0.8 * (2.0 * std::numbers::pi - 3.8), 1e-9);
  EXPECT_TRUE(spacing->odometry_moves);
}

TEST(ScanSpacingTest, AnEvenCountTakesTheMiddleTwo) {
  // Gaps 1 and 3 s: median (rank 0.5) 2, p95 (rank 0.95) 1 + 0.95 * 2 = 2.9. Travel 0.2 and 0.6 m:
  // median 0.4, p95 0.2 + 0.95 * 0.4 = 0.58.
  const std::optional<ScanSpacing> spacing = ComputeScanSpacing(Made({{0, 0, 0, 0}, {1, 0.2, 0, 0}, {4, 0.8, 0, 0}}));
  ASSERT_TRUE(spacing);
  EXPECT_NEAR(spacing->gap_s.median, 2.0, 1e-12);
  EXPECT_NEAR(spacing->gap_s.p95, 2.9, 1e-12);
  EXPECT_NEAR(spacing->travel_m.median, 0.4, 1e-12);
  EXPECT_NEAR(spacing->travel_m.p95, 0.58, 1e-12);
  EXPECT_EQ(spacing->rotation_rad.median, 0.0);
}

TEST(ScanSpacingTest, OneScanHasNoSpacingAndAParkedOdometryNoVerdict) {
  EXPECT_FALSE(ComputeScanSpacing(Made({{0, 0, 0, 0}})));
  const std::optional<ScanSpacing> parked = ComputeScanSpacing(Made({{0, 5, 5, 1}, {10, 5, 5, 1}, {20, 5, 5, 1}}));
  ASSERT_TRUE(parked);
  EXPECT_FALSE(parked->odometry_moves);
  EXPECT_FALSE(TooSparseForScanMatching(*parked));
  EXPECT_EQ(SparseScanWarning(*parked), "");
}

TEST(ScanSpacingTest, TheThresholdRestsOnTheDensityStudy) {
  // docs/full-rate-intel.md's three densities of one intel span, median travel between scans (measured in
  // docs/data-density.md): every scan 0.0555 m (Cartographer 0.025 m), every 5th scan 0.2842 m (Cartographer
  // 0.18 m, vinySLAM no better than the wheels). The bound is their geometric mean, 0.1256 m, rounded down.
  const double bound = SparseScanThresholdInUse().median_travel_m;
  EXPECT_EQ(bound, 0.12);
  EXPECT_GT(bound, 0.0555);
  EXPECT_LT(bound, 0.2842);
}

TEST(ScanSpacingTest, MedianTravelBeyondTheThresholdIsSparseTimeAndRotationAreNot) {
  // Travel 0.11 m then 0.11 m: median 0.11, inside 0.12; scans 10 s apart and turning 1 rad each (a slow robot
  // turning in place between scans is shown, not judged): dense enough.
  const Sequence slow = Made({{0, 0, 0, 0}, {10, 0.11, 0, 1.0}, {20, 0.22, 0, 2.0}});
  EXPECT_EQ(TooSparseForScanMatching(*ComputeScanSpacing(slow)), false);
  EXPECT_EQ(SparseScanWarning(*ComputeScanSpacing(slow)), "");
  // Travel 0.13 m per step, 0.1 s apart, no turn: median 0.13, beyond 0.12: sparse.
  const Sequence far = Made({{0, 0, 0, 0}, {0.1, 0.13, 0, 0}, {0.2, 0.26, 0, 0}});
  EXPECT_EQ(TooSparseForScanMatching(*ComputeScanSpacing(far)), true);
  // Steps 0.05, 0.05, 1, 1, 1 m: sorted, the median (rank 2) is 1 m: sparse.
  const Sequence mostly_far =
      Made({{0, 0, 0, 0}, {1, 0.05, 0, 0}, {2, 0.1, 0, 0}, {3, 1.1, 0, 0}, {4, 2.1, 0, 0}, {5, 3.1, 0, 0}});
  EXPECT_EQ(TooSparseForScanMatching(*ComputeScanSpacing(mostly_far)), true);
  // Steps 0.05, 0.05, 0.05, 1, 1 m: median 0.05: a few long steps do not make a log sparse.
  const Sequence mostly_near =
      Made({{0, 0, 0, 0}, {1, 0.05, 0, 0}, {2, 0.1, 0, 0}, {3, 0.15, 0, 0}, {4, 1.15, 0, 0}, {5, 2.15, 0, 0}});
  EXPECT_EQ(TooSparseForScanMatching(*ComputeScanSpacing(mostly_near)), false);
  const std::string warning = SparseScanWarning(*ComputeScanSpacing(far));
  EXPECT_NE(warning.find("too far apart for scan matching"), std::string::npos) << warning;
  EXPECT_NE(warning.find("0.13 m apart at the median"), std::string::npos) << warning;
  EXPECT_NE(warning.find("beyond 0.12 m"), std::string::npos) << warning;
  EXPECT_NE(warning.find("docs/data-density.md"), std::string::npos) << warning;
}

TEST(ScanSpacingTest, TheJsonBlockReadsBack) {
  const ScanSpacing spacing = *ComputeScanSpacing(Made({{0, 0, 0, 0}, {1, 0.2, 0, 0}, {4, 0.8, 0, 0.5}}));
  const nlohmann::json block = ScanSpacingJson(spacing);
  EXPECT_EQ(block.at("steps"), 2);
  EXPECT_NEAR(block.at("gap_s").at("median").get<double>(), 2.0, 1e-12);
  EXPECT_NEAR(block.at("travel_m").at("p95").get<double>(), 0.58, 1e-12);
  EXPECT_EQ(block.at("motion_from"), "odometry poses at the scans");
  EXPECT_EQ(block.at("too_sparse_for_scan_matching"), true);  // median travel 0.4 m
  EXPECT_EQ(block.at("threshold").at("median_travel_m"), 0.12);
  EXPECT_EQ(ScanSpacingFromJson(block), spacing);
  nlohmann::json broken = block;
  broken["travel_m"].erase("p95");
  EXPECT_THROW(ScanSpacingFromJson(broken), InputError);
}

}  // namespace
}  // namespace slamsweep::evaluator
