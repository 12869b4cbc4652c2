#include "evaluator/simulation/path_generator.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

// Distance from p to the segment [a, b].
double DistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

TEST(PathGeneratorTest, StraightLineAtConstantSpeed) {
  // 10 m at 0.5 m/s sampled at 10 Hz: 20 s, 201 poses 0.05 m apart, heading 45 degrees.
  const double d = 10.0 / std::sqrt(2.0);
  const std::vector<Eigen::Vector2d> waypoints = {{1.0, 2.0}, {1.0 + d, 2.0 + d}};
  const Trajectory path = FollowWaypoints(waypoints, PathOptions{});
  ASSERT_EQ(path.size(), 201u);
  for (std::size_t k = 0; k < path.size(); ++k) {
    EXPECT_NEAR(path.stamps_s()[k], 0.1 * k, 1e-12);
    EXPECT_NEAR(path.poses()[k].position.x(), 1.0 + 0.05 * k / std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(path.poses()[k].position.y(), 2.0 + 0.05 * k / std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(path.poses()[k].Yaw(), std::numbers::pi / 4, 1e-12);
  }
}

TEST(PathGeneratorTest, RightAngleIsRoundedWithAnArcAtTheSameSpeed) {
  // A 90 degree left turn: the arc of radius 0.4 m keeps speed 0.5 m/s, so consecutive poses are
  // 0.05 m apart (a chord on the arc is shorter by a negligible 4e-5 m), the heading changes by
  // at most 0.05 / 0.4 rad per step, and the path never leaves the polyline by more than the
  // fillet's gap r (sqrt(2) - 1) = 0.166 m.
  const std::vector<Eigen::Vector2d> waypoints = {{0, 0}, {4, 0}, {4, 3}};
  const Trajectory path = FollowWaypoints(waypoints, PathOptions{});
  for (std::size_t k = 1; k < path.size(); ++k) {
    const Pose& a = path.poses()[k - 1];
    const Pose& b = path.poses()[k];
    EXPECT_NEAR((b.position - a.position).norm(), 0.05, 1e-4) << k;
    EXPECT_LE(std::abs(NormalizeAngleRad(b.Yaw() - a.Yaw())), 0.125 + 1e-9) << k;
    const Eigen::Vector2d p = b.position.head<2>();
    const double off =
        std::min(DistanceToSegment(p, waypoints[0], waypoints[1]), DistanceToSegment(p, waypoints[1], waypoints[2]));
    EXPECT_LE(off, 0.4 * (std::sqrt(2.0) - 1.0) + 1e-9) << k;
  }
  EXPECT_NEAR(path.poses().back().Yaw(), std::numbers::pi / 2, 1e-9);
  // Path length 7 - 2 * 0.4 + 0.4 * pi / 2 = 6.828 m -> 13.657 s -> 137 poses.
  EXPECT_EQ(path.size(), 137u);
}

TEST(PathGeneratorTest, UTurnIsMadeInPlaceAtTheTurnRate) {
  // Out 2 m and back: a half turn in place at 0.8 rad/s takes pi / 0.8 = 3.93 s.
  const std::vector<Eigen::Vector2d> waypoints = {{0, 0}, {2, 0}, {0, 0}};
  const Trajectory path = FollowWaypoints(waypoints, PathOptions{});
  int turning = 0;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const Pose& a = path.poses()[k - 1];
    const Pose& b = path.poses()[k];
    EXPECT_LE(std::abs(b.position.y()), 1e-9);
    const double turned = std::abs(NormalizeAngleRad(b.Yaw() - a.Yaw()));
    EXPECT_LE(turned, 0.08 + 1e-9);
    if (turned > 1e-9) {
      ++turning;
      EXPECT_NEAR(b.position.x(), 2.0, 0.05);
    }
  }
  EXPECT_NEAR(turning, std::numbers::pi / 0.8 * 10.0, 1.5);
  EXPECT_EQ(path.size(), static_cast<std::size_t>(std::floor((8.0 + std::numbers::pi / 0.8) * 10.0)) + 1);
}

TEST(PathGeneratorTest, IgnoresRepeatedWaypointsAndRejectsBadInput) {
  const std::vector<Eigen::Vector2d> repeated = {{0, 0}, {0, 0}, {1, 0}, {1, 0}};
  EXPECT_EQ(FollowWaypoints(repeated, PathOptions{}).size(), 21u);
  const std::vector<Eigen::Vector2d> one = {{0, 0}, {0, 0}};
  EXPECT_THAT([&] { FollowWaypoints(one, PathOptions{}); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("two distinct")));
  const std::vector<Eigen::Vector2d> nan = {{0, 0}, {std::nan(""), 0}};
  EXPECT_THAT([&] { FollowWaypoints(nan, PathOptions{}); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("waypoint 1")));
  PathOptions options;
  options.speed_m_per_s = 0.0;
  EXPECT_THAT([&] { FollowWaypoints(repeated, options); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("speed_m_per_s")));
  options = {};
  options.rate_hz = 1e9;
  const std::vector<Eigen::Vector2d> long_line = {{0, 0}, {1000, 0}};
  EXPECT_THAT([&] { FollowWaypoints(long_line, options); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("10 million")));
}

TEST(PathGeneratorTest, JsonRoundTripAndStrictReading) {
  PathOptions options;
  options.rate_hz = 40.0;
  EXPECT_EQ(PathOptionsFromJson(nlohmann::json(options)), options);
  EXPECT_THAT(
      [] {
        PathOptionsFromJson(nlohmann::json{{"speed", 1.0}});
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("path.speed: unknown option")));
  EXPECT_THAT(
      [] {
        PathOptionsFromJson(nlohmann::json{{"rate_hz", -1.0}});
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("path.rate_hz")));
}

}  // namespace
}  // namespace slamsweep::evaluator
