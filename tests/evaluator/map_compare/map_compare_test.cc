#include "evaluator/map_compare/map_compare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/map_compare/map_resample.h"

namespace slamsweep::evaluator {
namespace {

/// A 120 x 80-cell floor (0.05 m cells): free inside, walls around, two inner walls, unknown outside.
OccupancyGrid Floor(double origin_x = -1.0, double origin_y = -2.0) {
  OccupancyGrid grid(120, 80, 0.05, {origin_x, origin_y, 0.0});
  for (int r = 10; r < 70; ++r) {
    for (int c = 10; c < 110; ++c) {
      const bool wall = r == 10 || r == 69 || c == 10 || c == 109 || (c == 50 && r < 50) || (r == 40 && c > 70);
      grid.at(r, c) = wall ? 1.0f : 0.0f;
    }
  }
  return grid;
}

/// Distances between cells of a 0.05 m grid are compared to a fifth of a cell.
constexpr double kFifthOfACellM = 0.01;

/// Only vertical walls: shifting along x moves every occupied cell away from its twin by the shift.
OccupancyGrid VerticalWalls() {
  OccupancyGrid grid(100, 60, 0.05);
  for (int r = 0; r < 60; ++r) {
    for (int c = 0; c < 100; ++c) grid.at(r, c) = (c == 20 || c == 70) ? 1.0f : 0.0f;
  }
  return grid;
}

TEST(MapCompareTest, AMapAgainstItselfIsPerfect) {
  const OccupancyGrid map = Floor();
  const MapComparison result = CompareMaps(map, map);
  EXPECT_DOUBLE_EQ(result.chamfer_m, 0.0);
  EXPECT_DOUBLE_EQ(result.estimate_to_reference_max_m, 0.0);
  EXPECT_DOUBLE_EQ(result.f1, 1.0);
  EXPECT_DOUBLE_EQ(result.iou_occupied, 1.0);
  EXPECT_DOUBLE_EQ(result.iou_free, 1.0);
  EXPECT_GT(result.estimate_occupied, 300u);
}

TEST(MapCompareTest, AShiftOfKCellsIsKCellsAway) {
  const OccupancyGrid reference = VerticalWalls();
  for (int k : {1, 3, 6}) {
    OccupancyGrid shifted = reference;
    shifted.origin.x_m += k * reference.resolution_m;
    const MapComparison result = CompareMaps(shifted, reference);
    // A fifth of a cell: a one-cell shift must not read as none (or as two).
    EXPECT_NEAR(result.estimate_to_reference_mean_m, k * 0.05, kFifthOfACellM) << k;
    EXPECT_NEAR(result.reference_to_estimate_mean_m, k * 0.05, kFifthOfACellM) << k;
    EXPECT_NEAR(result.estimate_to_reference_max_m, k * 0.05, kFifthOfACellM) << k;
    // Within the 2-cell radius only for k <= 2.
    EXPECT_EQ(result.f1 == 1.0, k <= 2) << k;
    // The same shift given as the transform undoes it.
    MapCompareOptions options;
    options.transform.x_m = -k * reference.resolution_m;
    EXPECT_NEAR(CompareMaps(shifted, reference, options).chamfer_m, 0.0, 1e-9) << k;
  }
}

TEST(MapCompareTest, AShiftAlongYOrBothAxesIsAlsoKCellsAway) {
  // Only horizontal walls: a shift along y moves every wall cell off its twin by the shift.
  OccupancyGrid reference(60, 100, 0.05);
  for (int r = 0; r < 100; ++r) {
    for (int c = 0; c < 60; ++c) reference.at(r, c) = (r == 20 || r == 70) ? 1.0f : 0.0f;
  }
  for (int k : {1, 2, 4}) {
    OccupancyGrid shifted = reference;
    shifted.origin.y_m -= k * reference.resolution_m;
    const MapComparison result = CompareMaps(shifted, reference);
    EXPECT_NEAR(result.estimate_to_reference_mean_m, k * 0.05, kFifthOfACellM) << k;
    EXPECT_NEAR(result.reference_to_estimate_mean_m, k * 0.05, kFifthOfACellM) << k;
  }
  // A single occupied cell moved by (3, 4) cells is 5 cells away.
  OccupancyGrid dot(40, 40, 0.05, {}, 0.0f);
  dot.at(20, 20) = 1.0f;
  OccupancyGrid moved = dot;
  moved.origin.x_m += 3 * 0.05;
  moved.origin.y_m += 4 * 0.05;
  EXPECT_NEAR(CompareMaps(moved, dot).chamfer_m, 5 * 0.05, 1e-6);
}

TEST(MapCompareTest, PaddingWithUnknownCellsChangesNothing) {
  const OccupancyGrid map = Floor();
  OccupancyGrid padded(map.width + 70, map.height + 30, map.resolution_m,
                       {map.origin.x_m - 40 * map.resolution_m, map.origin.y_m - 10 * map.resolution_m, 0.0});
  for (int r = 0; r < map.height; ++r) {
    for (int c = 0; c < map.width; ++c) padded.at(r + 20, c + 40) = map.at(r, c);
  }
  OccupancyGrid other = Floor(-1.0 + 0.1, -2.0);  // two cells off, so the scores are not trivial
  const MapComparison plain = CompareMaps(other, map);
  const MapComparison with_padding = CompareMaps(other, padded);
  EXPECT_DOUBLE_EQ(plain.chamfer_m, with_padding.chamfer_m);
  EXPECT_DOUBLE_EQ(plain.f1, with_padding.f1);
  EXPECT_DOUBLE_EQ(plain.iou_occupied, with_padding.iou_occupied);
  EXPECT_DOUBLE_EQ(plain.iou_free, with_padding.iou_free);
  EXPECT_EQ(plain.known_in_both, with_padding.known_in_both);
  // The same padding on the estimate's side.
  const MapComparison padded_estimate = CompareMaps(padded, other);
  const MapComparison plain_estimate = CompareMaps(map, other);
  EXPECT_DOUBLE_EQ(plain_estimate.chamfer_m, padded_estimate.chamfer_m);
  EXPECT_DOUBLE_EQ(plain_estimate.f1, padded_estimate.f1);
  EXPECT_DOUBLE_EQ(plain_estimate.iou_free, padded_estimate.iou_free);
}

TEST(MapCompareTest, MoreNoiseNeverRaisesF1) {
  const OccupancyGrid reference = Floor();
  double previous_f1 = 1.0 + 1e-12;
  for (double fraction : {0.0, 0.01, 0.03, 0.1, 0.3}) {
    OccupancyGrid noisy = reference;
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::mt19937 draw(7);  // the same cells in the same order: noise levels are nested
    for (float& cell : noisy.cells) {
      if (OccupancyGrid::IsUnknown(cell)) continue;
      if (uniform(draw) < fraction) cell = 1.0f - cell;
    }
    const double f1 = CompareMaps(noisy, reference).f1;
    EXPECT_LE(f1, previous_f1) << fraction;
    previous_f1 = f1;
  }
  EXPECT_LT(previous_f1, 0.5);
}

TEST(MapCompareTest, IcpFindsAnUnknownRigidOffset) {
  const OccupancyGrid reference = Floor();
  OccupancyGrid moved = reference;
  moved.origin.x_m += 0.15;
  moved.origin.y_m -= 0.10;
  MapCompareOptions options;
  EXPECT_GT(CompareMaps(moved, reference, options).chamfer_m, 0.05);
  options.refine_with_icp = true;
  const MapComparison refined = CompareMaps(moved, reference, options);
  EXPECT_LT(refined.chamfer_m, 0.01);
  EXPECT_NEAR(refined.transform.x_m, -0.15, 0.026);
  EXPECT_NEAR(refined.transform.y_m, 0.10, 0.026);
}

/// Brute force over every pair of occupied cells: an independent computation of the distances,
/// accuracy and completeness for maps on one lattice.
struct BruteForce {
  double est_to_ref_mean = 0, ref_to_est_mean = 0, accuracy = 0, completeness = 0;
};

BruteForce BruteForceScores(const OccupancyGrid& estimate, const OccupancyGrid& reference, int radius) {
  std::vector<std::pair<int, int>> est, ref;
  for (int r = 0; r < estimate.height; ++r) {
    for (int c = 0; c < estimate.width; ++c) {
      if (estimate.at(r, c) >= 0.65f) est.push_back({r, c});
      if (reference.at(r, c) >= 0.65f) ref.push_back({r, c});
    }
  }
  const auto directed = [&](const auto& from, const auto& to, double& mean, double& within) {
    double sum = 0;
    std::size_t close = 0;
    for (const auto& [r, c] : from) {
      double best = 1e18;
      for (const auto& [r2, c2] : to) best = std::min(best, std::hypot(r - r2, c - c2));
      sum += best;
      close += best <= radius;
    }
    mean = sum / from.size() * estimate.resolution_m;
    within = static_cast<double>(close) / from.size();
  };
  BruteForce scores;
  directed(est, ref, scores.est_to_ref_mean, scores.accuracy);
  directed(ref, est, scores.ref_to_est_mean, scores.completeness);
  return scores;
}

TEST(MapCompareTest, AgreesWithABruteForceComputation) {
  std::mt19937 random(3);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int trial = 0; trial < 5; ++trial) {
    OccupancyGrid estimate(60, 40, 0.05), reference(60, 40, 0.05);
    for (std::size_t i = 0; i < estimate.cells.size(); ++i) {
      estimate.cells[i] = uniform(random) < 0.05f ? 1.0f : 0.0f;
      reference.cells[i] = uniform(random) < 0.05f ? 1.0f : 0.0f;
    }
    const MapComparison result = CompareMaps(estimate, reference);
    const BruteForce expected = BruteForceScores(estimate, reference, 2);
    EXPECT_NEAR(result.estimate_to_reference_mean_m, expected.est_to_ref_mean, 1e-5) << trial;
    EXPECT_NEAR(result.reference_to_estimate_mean_m, expected.ref_to_est_mean, 1e-5) << trial;
    EXPECT_NEAR(result.accuracy, expected.accuracy, 1e-12) << trial;
    EXPECT_NEAR(result.completeness, expected.completeness, 1e-12) << trial;
  }
}

TEST(MapResampleTest, TheSameCellSizeChangesNothing) {
  const OccupancyGrid map = Floor();
  const OccupancyGrid same = ResampleToResolution(map, 0.05);
  EXPECT_EQ(same.cells, map.cells);
  EXPECT_THROW(ResampleToResolution(map, 0.0), InputError);
}

TEST(MapResampleTest, CoarserCellsKeepOneCellWallsAndUnknownStaysUnknown) {
  // 0.05 m -> 0.1 m: a wall one fine cell thick is still a wall; the unknown border stays unknown.
  const OccupancyGrid fine = Floor();
  const OccupancyGrid coarse = ResampleToResolution(fine, 0.1);
  EXPECT_EQ(coarse.width, 60);
  EXPECT_EQ(coarse.height, 40);
  EXPECT_DOUBLE_EQ(coarse.origin.x_m, fine.origin.x_m);
  EXPECT_DOUBLE_EQ(coarse.origin.y_m, fine.origin.y_m);
  // Fine column 50 (the inner wall, rows 10..49) lies in coarse column 25; fine row 40 in coarse row 20.
  EXPECT_EQ(coarse.at(10, 25), 1.0f);
  EXPECT_EQ(coarse.at(20, 45), 1.0f);
  EXPECT_EQ(coarse.at(15, 15), 0.0f);  // fine rows 30-31, columns 30-31: free
  EXPECT_TRUE(OccupancyGrid::IsUnknown(coarse.at(1, 1)));
}

TEST(MapResampleTest, FinerCellsSplitEachCell) {
  OccupancyGrid coarse(3, 2, 0.1, {1.0, 2.0, 0.0}, 0.0f);
  coarse.at(0, 2) = 1.0f;                     // top right occupied
  coarse.at(1, 0) = OccupancyGrid::kUnknown;  // bottom left unknown
  const OccupancyGrid fine = ResampleToResolution(coarse, 0.05);
  ASSERT_EQ(fine.width, 6);
  ASSERT_EQ(fine.height, 4);
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 6; ++c) {
      const float expected = coarse.at(r / 2, c / 2);
      EXPECT_EQ(fine.at(r, c), expected) << r << " " << c;
    }
  }
}

TEST(MapCompareTest, FarWallsAgreeWithABruteForceComputation) {
  // A few scattered occupied cells: most distances exceed the 64-cell row scan, so the exact
  // lower-envelope pass answers them.
  std::mt19937 random(11);
  std::uniform_int_distribution<int> row(0, 199), col(0, 299);
  for (int trial = 0; trial < 3; ++trial) {
    OccupancyGrid estimate(300, 200, 0.05, {}, 0.0f), reference(300, 200, 0.05, {}, 0.0f);
    for (int i = 0; i < 6; ++i) estimate.at(row(random), col(random)) = 1.0f;
    for (int i = 0; i < 4; ++i) reference.at(row(random), col(random)) = 1.0f;
    const MapComparison result = CompareMaps(estimate, reference);
    const BruteForce expected = BruteForceScores(estimate, reference, 2);
    EXPECT_NEAR(result.estimate_to_reference_mean_m, expected.est_to_ref_mean, 1e-9) << trial;
    EXPECT_NEAR(result.reference_to_estimate_mean_m, expected.ref_to_est_mean, 1e-9) << trial;
    EXPECT_GT(result.estimate_to_reference_max_m, 64 * 0.05) << trial;
  }
}

TEST(MapCompareTest, ARotatedCopyPlacedBackIsPerfect) {
  // The floor turned by 90 degrees about the origin (cell (r, c) of the copy is cell (c, ...) of
  // the original), with the transform that turns it back: every cell lands on its twin.
  const OccupancyGrid floor = Floor(0.0, 0.0);
  OccupancyGrid turned(floor.height, floor.width, floor.resolution_m, {-floor.height * floor.resolution_m, 0.0, 0.0});
  for (int r = 0; r < floor.height; ++r) {
    for (int c = 0; c < floor.width; ++c) {
      // World (x, y) -> (-y, x): row from the bottom becomes the column counted from the right.
      const int from_bottom = floor.height - 1 - r;
      turned.at(turned.height - 1 - c, turned.width - 1 - from_bottom) = floor.at(r, c);
    }
  }
  MapCompareOptions options;
  options.transform.yaw_rad = -M_PI / 2;  // back from (-y, x) to (x, y)
  const MapComparison result = CompareMaps(turned, floor, options);
  EXPECT_NEAR(result.chamfer_m, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(result.f1, 1.0);
  EXPECT_DOUBLE_EQ(result.iou_free, 1.0);
  EXPECT_EQ(result.estimate_occupied, result.reference_occupied);
}

TEST(MapCompareTest, RefusesMapsItCannotCompare) {
  OccupancyGrid coarse = Floor();
  coarse.resolution_m = 0.1;
  EXPECT_THROW(CompareMaps(coarse, Floor()), InputError);
  const OccupancyGrid empty(10, 10, 0.05, {}, 0.0f);
  EXPECT_THROW(CompareMaps(empty, Floor()), InputError);
}

}  // namespace
}  // namespace slamsweep::evaluator
