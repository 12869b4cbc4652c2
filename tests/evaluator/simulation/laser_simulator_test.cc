#include "evaluator/simulation/laser_simulator.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

// A hand-made box room: 0.05 m cells, origin (0, 0), free interior x in [1, 6), y in [1, 4),
// walls one cell thick just outside it, unknown beyond.
OccupancyGrid BoxRoom() {
  OccupancyGrid grid(140, 100, 0.05);
  for (int row = 0; row < grid.height; ++row) {
    for (int col = 0; col < grid.width; ++col) {
      const int cell_y = grid.height - 1 - row;
      const bool inside_walls = col >= 19 && col < 121 && cell_y >= 19 && cell_y < 81;
      const bool interior = col >= 20 && col < 120 && cell_y >= 20 && cell_y < 80;
      if (interior) {
        grid.at(row, col) = 0.0f;
      } else if (inside_walls) {
        grid.at(row, col) = 1.0f;
      }
    }
  }
  return grid;
}

// Distance from (x, y) inside the box [1, 6] x [1, 4] to its border along angle a.
double DistanceToBox(double x, double y, double a) {
  const double c = std::cos(a), s = std::sin(a);
  double t = std::numeric_limits<double>::infinity();
  if (c > 1e-12) t = std::min(t, (6.0 - x) / c);
  if (c < -1e-12) t = std::min(t, (1.0 - x) / c);
  if (s > 1e-12) t = std::min(t, (4.0 - y) / s);
  if (s < -1e-12) t = std::min(t, (1.0 - y) / s);
  return t;
}

TEST(LaserSimulatorTest, RangesHitTheWallsOfABoxRoomAtTheirGeometricDistance) {
  const OccupancyGrid room = BoxRoom();
  const Pose robot = Pose::Planar(3.0, 2.0, 0.3);
  const LaserScan scan = SimulateScan(room, robot, 12.5, LaserOptions{});
  ASSERT_EQ(scan.BeamCount(), 360u);
  EXPECT_EQ(scan.stamp_s, 12.5);
  EXPECT_NEAR(scan.angle_increment_rad, 2.0 * std::numbers::pi / 360.0, 1e-15);
  EXPECT_NEAR(scan.angle_min_rad, -std::numbers::pi, 1e-15);
  for (std::size_t i = 0; i < scan.BeamCount(); ++i) {
    const double expected = DistanceToBox(3.0, 2.0, 0.3 + scan.BeamAngleRad(i));
    ASSERT_TRUE(scan.IsHit(scan.ranges_m[i])) << i;
    EXPECT_NEAR(scan.ranges_m[i], expected, 1e-5) << "beam " << i;
  }
  // The four principal directions, by hand: 3 m to x = 6, 2 m to y = 4, 2 m to x = 1, 1 m to y = 1.
  const Pose facing_x = Pose::Planar(3.0, 2.0, 0.0);
  LaserOptions four;
  four.beam_count = 4;
  const LaserScan cross = SimulateScan(room, facing_x, 0.0, four);
  EXPECT_FLOAT_EQ(cross.ranges_m[0], 2.0f);  // angle -pi
  EXPECT_FLOAT_EQ(cross.ranges_m[1], 1.0f);  // -pi / 2
  EXPECT_FLOAT_EQ(cross.ranges_m[2], 3.0f);  // 0
  EXPECT_FLOAT_EQ(cross.ranges_m[3], 2.0f);  // pi / 2
}

TEST(LaserSimulatorTest, SensorMountingShiftsAndTurnsTheBeams) {
  LaserOptions options;
  options.beam_count = 1;
  options.fov_rad = 0.1;
  // Mounted 0.5 m ahead of the robot centre and looking left.
  options.sensor_pose_on_robot = Pose::Planar(0.5, 0.0, std::numbers::pi / 2);
  const LaserScan scan = SimulateScan(BoxRoom(), Pose::Planar(3.0, 2.0, 0.0), 0.0, options);
  EXPECT_EQ(scan.angle_min_rad, 0.0);
  EXPECT_NEAR(scan.ranges_m[0], 2.0, 1e-6);  // from (3.5, 2) up to y = 4
  EXPECT_EQ(scan.sensor_pose_on_robot.position.x(), 0.5);
}

TEST(LaserSimulatorTest, PartialFieldOfViewSpansItsEnds) {
  LaserOptions options;
  options.beam_count = 181;
  options.fov_rad = std::numbers::pi;
  const LaserScan scan = SimulateScan(BoxRoom(), Pose::Planar(3.0, 2.0, 0.0), 0.0, options);
  EXPECT_NEAR(scan.angle_min_rad, -std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(scan.BeamAngleRad(180), std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(scan.ranges_m[90], 3.0, 1e-6);
}

TEST(LaserSimulatorTest, NothingWithinRangeIsANoReturn) {
  LaserOptions options;
  options.range_max_m = 1.5;
  const LaserScan scan = SimulateScan(BoxRoom(), Pose::Planar(3.5, 2.5, 0.0), 0.0, options);
  for (float range : scan.ranges_m) {
    EXPECT_FALSE(scan.IsHit(range));
    EXPECT_GE(range, 1.5f);
  }
  // Unknown cells are transparent and leaving the grid hits nothing.
  OccupancyGrid open(100, 100, 0.05);
  EXPECT_LT(CastRay(open, 2.5, 2.5, 0.7, 100.0), 0.0);
  // Outside the grid or inside a wall.
  EXPECT_LT(CastRay(BoxRoom(), -1.0, 2.0, 0.0, 10.0), 0.0);
  EXPECT_EQ(CastRay(BoxRoom(), 0.97, 2.0, 0.0, 10.0), 0.0);
}

TEST(LaserSimulatorTest, InvalidOptionsAreInputErrors) {
  LaserOptions options;
  options.beam_count = 0;
  EXPECT_THAT([&] { SimulateScan(BoxRoom(), Pose(), 0.0, options); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("beam_count")));
  options = {};
  options.range_max_m = 0.01;
  EXPECT_THAT([&] { SimulateScan(BoxRoom(), Pose(), 0.0, options); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("range_max_m")));
  options = {};
  options.fov_rad = 7.0;
  EXPECT_THAT([&] { ValidateLaserOptions(options); }, ::testing::ThrowsMessage<InputError>(HasSubstr("fov_rad")));
  EXPECT_THAT(
      [] {
        LaserOptionsFromJson(nlohmann::json{{"beams", 10}});
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("laser.beams: unknown option")));
}

TEST(LaserSimulatorTest, JsonRoundTrip) {
  LaserOptions options;
  options.beam_count = 541;
  options.sensor_pose_on_robot = Pose::Planar(0.2, -0.1, 0.5);
  const LaserOptions back = LaserOptionsFromJson(nlohmann::json(options));
  EXPECT_EQ(back.beam_count, 541);
  EXPECT_NEAR(back.sensor_pose_on_robot.Yaw(), 0.5, 1e-12);
  EXPECT_NEAR(back.sensor_pose_on_robot.position.y(), -0.1, 1e-15);
}

}  // namespace
}  // namespace slamsweep::evaluator
