#include "evaluator/borders/polygon_simplify.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <vector>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::ElementsAre;

TEST(PolygonSimplifyTest, RectangleKeepsCornersAndDropsCollinearPoints) {
  // A 3 x 2 rectangle walked through every integer point.
  const std::vector<PlanarPoint> ring = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1},
                                         {3, 2}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  EXPECT_THAT(SimplifyClosedRing(ring, 0.0), ElementsAre(0u, 3u, 5u, 8u));
  EXPECT_THAT(SimplifyClosedRing(ring, 1.0), ElementsAre(0u, 3u, 5u, 8u));
}

TEST(PolygonSimplifyTest, DiagonalStaircaseIsReducedToItsEnds) {
  // A right triangle whose hypotenuse is a staircase of diagonal steps, as traced borders are.
  const std::vector<PlanarPoint> ring = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {2, 1}, {1, 2}, {0, 3}, {0, 2}, {0, 1}};
  EXPECT_THAT(SimplifyClosedRing(ring, 0.0), ElementsAre(0u, 3u, 6u));
}

TEST(PolygonSimplifyTest, StartPointInTheMiddleOfAnEdgeIsDropped) {
  // (1,0) lies on the edge (0,0)-(2,0): the anchors are chosen by shape, so it can go.
  const std::vector<PlanarPoint> ring = {{1, 0}, {2, 0}, {2, 1}, {0, 1}, {0, 0}};
  EXPECT_THAT(SimplifyClosedRing(ring, 0.0), ElementsAre(1u, 2u, 3u, 4u));
}

TEST(PolygonSimplifyTest, ToleranceIsAStrictDistanceLimit) {
  // (2, 0.5) is 0.5 from the edge (0,0)-(4,0); (2,3) lies on the edge (4,3)-(0,3).
  const std::vector<PlanarPoint> ring = {{0, 0}, {2, 0.5}, {4, 0}, {4, 3}, {2, 3}, {0, 3}};
  EXPECT_THAT(SimplifyClosedRing(ring, 0.4), ElementsAre(0u, 1u, 2u, 3u, 5u));
  EXPECT_THAT(SimplifyClosedRing(ring, 0.5), ElementsAre(0u, 2u, 3u, 5u));
}

TEST(PolygonSimplifyTest, LineWalkedThereAndBackKeepsBothEnds) {
  const std::vector<PlanarPoint> ring = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {2, 0}, {1, 0}};
  EXPECT_THAT(SimplifyClosedRing(ring, 0.0), ElementsAre(0u, 3u));
  EXPECT_THAT(SimplifyClosedRing(ring, 10.0), ElementsAre(0u, 3u));
}

TEST(PolygonSimplifyTest, LargeToleranceStillKeepsTwoAnchors) {
  const std::vector<PlanarPoint> ring = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
  // Farthest from point 0 is (4,3) (index 2); farthest from that is (0,0) (index 0).
  EXPECT_THAT(SimplifyClosedRing(ring, 100.0), ElementsAre(0u, 2u));
}

TEST(PolygonSimplifyTest, TinyRingsAndCoincidentPoints) {
  EXPECT_TRUE(SimplifyClosedRing({}, 1.0).empty());
  const std::vector<PlanarPoint> two = {{0, 0}, {1, 1}};
  EXPECT_THAT(SimplifyClosedRing(two, 1.0), ElementsAre(0u, 1u));
  const std::vector<PlanarPoint> same = {{2, 2}, {2, 2}, {2, 2}};
  EXPECT_THAT(SimplifyClosedRing(same, 0.0), ElementsAre(0u));
}

TEST(PolygonSimplifyTest, BadToleranceIsAnInputError) {
  const std::vector<PlanarPoint> ring = {{0, 0}, {1, 0}, {1, 1}};
  EXPECT_THROW(SimplifyClosedRing(ring, -1.0), InputError);
  EXPECT_THROW(SimplifyClosedRing(ring, std::numeric_limits<double>::quiet_NaN()), InputError);
  EXPECT_THROW(SimplifyClosedRing(ring, std::numeric_limits<double>::infinity()), InputError);
}

TEST(PolygonSimplifyTest, MillionPointRingNeedsNoRecursion) {
  // A fine circle: every point is a genuine (if tiny) corner at tolerance 0, which is the
  // deepest possible subdivision; a recursive implementation would risk the stack here.
  const std::size_t n = 1'000'000;
  std::vector<PlanarPoint> ring;
  ring.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    ring.push_back({1e4 * std::cos(angle), 1e4 * std::sin(angle)});
  }
  const std::vector<std::size_t> kept = SimplifyClosedRing(ring, 1.0);
  // Sagitta of a chord of length L on radius R is L^2 / (8R): tolerance 1 allows chords up to
  // sqrt(8e4) ~ 283, so roughly 2 pi 1e4 / 283 ~ 222 vertices; DP keeps between that and twice it.
  EXPECT_GT(kept.size(), 200u);
  EXPECT_LT(kept.size(), 500u);
}

}  // namespace
}  // namespace slamsweep::evaluator
