#include "evaluator/simulation/floor_plan.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <queue>

#include "evaluator/core/input_error.h"
#include "evaluator/simulation/path_generator.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

struct Cell {
  int row;
  int col;
};

Cell CellOf(const OccupancyGrid& grid, double x_m, double y_m) {
  const int col = static_cast<int>(std::floor((x_m - grid.origin.x_m) / grid.resolution_m));
  const int row = grid.height - 1 - static_cast<int>(std::floor((y_m - grid.origin.y_m) / grid.resolution_m));
  return {row, col};
}

bool IsWall(const OccupancyGrid& grid, int row, int col) { return grid.at(row, col) >= 0.5f; }

TEST(FloorPlanTest, SameSeedSamePlanDifferentSeedDifferentPlan) {
  FloorPlanOptions options;
  const FloorPlan a = GenerateFloorPlan(options);
  const FloorPlan b = GenerateFloorPlan(options);
  EXPECT_EQ(a.grid.cells, b.grid.cells);
  options.seed = 2;
  const FloorPlan c = GenerateFloorPlan(options);
  EXPECT_NE(a.grid.cells, c.grid.cells);
}

TEST(FloorPlanTest, BuildingIsClosedAndSurroundedByUnknownMargin) {
  FloorPlanOptions options;
  options.margin_m = 0.5;  // 10 cells
  const FloorPlan plan = GenerateFloorPlan(options);
  const OccupancyGrid& grid = plan.grid;
  ASSERT_EQ(plan.rooms.size(), 6u);
  for (int col = 0; col < grid.width; ++col) {
    EXPECT_TRUE(OccupancyGrid::IsUnknown(grid.at(0, col)));
    EXPECT_TRUE(OccupancyGrid::IsUnknown(grid.at(grid.height - 1, col)));
    // The outer wall: first and last rows of the building.
    if (col >= 10 && col < grid.width - 10) {
      EXPECT_TRUE(IsWall(grid, 10, col)) << col;
      EXPECT_TRUE(IsWall(grid, grid.height - 11, col)) << col;
    }
  }
  for (int row = 10; row < grid.height - 10; ++row) {
    EXPECT_TRUE(IsWall(grid, row, 10)) << row;
    EXPECT_TRUE(IsWall(grid, row, grid.width - 11)) << row;
  }
  // Every cell inside the building is known; none outside is.
  int unknown_inside = 0;
  for (int row = 10; row < grid.height - 10; ++row) {
    for (int col = 10; col < grid.width - 10; ++col) unknown_inside += OccupancyGrid::IsUnknown(grid.at(row, col));
  }
  EXPECT_EQ(unknown_inside, 0);
}

TEST(FloorPlanTest, EveryRoomIsReachableThroughItsDoorAndItsTourIsFree) {
  const FloorPlan plan = GenerateFloorPlan(FloorPlanOptions{});
  const OccupancyGrid& grid = plan.grid;
  // Flood fill over free cells from the middle of the corridor.
  std::vector<char> reached(grid.CellCount(), 0);
  const Cell start = CellOf(grid, plan.corridor.CenterXM(), plan.corridor.CenterYM());
  std::queue<Cell> open;
  open.push(start);
  reached[static_cast<std::size_t>(start.row) * grid.width + start.col] = 1;
  while (!open.empty()) {
    const Cell cell = open.front();
    open.pop();
    const int offsets[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& offset : offsets) {
      const int row = cell.row + offset[0], col = cell.col + offset[1];
      if (row < 0 || col < 0 || row >= grid.height || col >= grid.width) continue;
      const float p = grid.at(row, col);
      char& seen = reached[static_cast<std::size_t>(row) * grid.width + col];
      if (seen || OccupancyGrid::IsUnknown(p) || p >= 0.5f) continue;
      seen = 1;
      open.push({row, col});
    }
  }
  for (const Room& room : plan.rooms) {
    const Cell door = CellOf(grid, room.door_m.x(), room.door_m.y());
    EXPECT_TRUE(reached[static_cast<std::size_t>(door.row) * grid.width + door.col]);
    for (const Eigen::Vector2d& point : room.tour_m) {
      EXPECT_GT(point.x(), room.interior.min_x_m);
      EXPECT_LT(point.x(), room.interior.max_x_m);
      EXPECT_GT(point.y(), room.interior.min_y_m);
      EXPECT_LT(point.y(), room.interior.max_y_m);
      const Cell cell = CellOf(grid, point.x(), point.y());
      EXPECT_TRUE(reached[static_cast<std::size_t>(cell.row) * grid.width + cell.col]);
    }
  }
}

TEST(FloorPlanTest, TheTourPathKeepsClearOfWallsAndClutter) {
  // Sample the robot's path and check a disc of 0.25 m around every pose is free.
  for (std::uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
    FloorPlanOptions options;
    options.seed = seed;
    options.clutter_per_room = 6;
    const FloorPlan plan = GenerateFloorPlan(options);
    const Trajectory path = FollowWaypoints(TourWaypoints(plan), PathOptions{});
    ASSERT_GT(path.size(), 100u);
    for (const Pose& pose : path.poses()) {
      for (int k = 0; k < 16; ++k) {
        const double angle = k * 2.0 * 3.141592653589793 / 16.0;
        for (double radius : {0.0, 0.1, 0.25}) {
          const Cell cell = CellOf(plan.grid, pose.position.x() + radius * std::cos(angle),
                                   pose.position.y() + radius * std::sin(angle));
          ASSERT_FALSE(IsWall(plan.grid, cell.row, cell.col))
              << "seed " << seed << " pose (" << pose.position.x() << ", " << pose.position.y() << ")";
        }
      }
    }
    // The loop closes: the path ends where it started.
    EXPECT_LT((path.poses().back().position - path.poses().front().position).norm(), 0.06);
  }
}

TEST(FloorPlanTest, SizesFollowTheOptions) {
  // Two rooms per side of exactly 4 x 3 m (no jitter), 2 m corridor, 0.1 m walls, 0.1 m cells:
  // width 0.1 + 4 + 0.1 + 4 + 0.1 = 8.3 m, height 4 * 0.1 + 3 + 2 + 3 = 8.4 m, plus 2 x 1 m margin.
  FloorPlanOptions options;
  options.resolution_m = 0.1;
  options.rooms_per_side = 2;
  options.room_width_m = 4.0;
  options.room_width_jitter_m = 0.0;
  options.room_depth_m = 3.0;
  options.room_depth_jitter_m = 0.0;
  options.wall_thickness_m = 0.1;
  const FloorPlan plan = GenerateFloorPlan(options);
  EXPECT_EQ(plan.grid.width, 83 + 20);
  EXPECT_EQ(plan.grid.height, 84 + 20);
  EXPECT_NEAR(plan.corridor.max_y_m - plan.corridor.min_y_m, 2.0, 1e-9);
  EXPECT_NEAR(plan.corridor.max_x_m - plan.corridor.min_x_m, 8.1, 1e-9);
  for (const Room& room : plan.rooms) {
    EXPECT_NEAR(room.interior.max_x_m - room.interior.min_x_m, 4.0, 1e-9);
    EXPECT_NEAR(room.interior.max_y_m - room.interior.min_y_m, 3.0, 1e-9);
  }
}

TEST(FloorPlanTest, InvalidOptionsAreInputErrorsNamingTheOption) {
  FloorPlanOptions options;
  options.door_width_m = 4.5;
  EXPECT_THAT([&] { GenerateFloorPlan(options); }, ::testing::ThrowsMessage<InputError>(HasSubstr("room_width_m")));
  options = {};
  options.rooms_per_side = 0;
  EXPECT_THAT([&] { GenerateFloorPlan(options); }, ::testing::ThrowsMessage<InputError>(HasSubstr("rooms_per_side")));
  options = {};
  options.wall_thickness_m = 0.01;
  EXPECT_THAT([&] { GenerateFloorPlan(options); }, ::testing::ThrowsMessage<InputError>(HasSubstr("wall_thickness_m")));
  options = {};
  options.room_depth_m = 1e12;  // must be refused before it is rounded to cells
  EXPECT_THAT([&] { GenerateFloorPlan(options); }, ::testing::ThrowsMessage<InputError>(HasSubstr("250 million")));
  options = {};
  options.clutter_max_size_m = 1e9;
  EXPECT_THAT([&] { GenerateFloorPlan(options); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("clutter_max_size_m")));
  options = {};
  options.resolution_m = 1e-4;
  EXPECT_THAT([&] { GenerateFloorPlan(options); }, ::testing::ThrowsMessage<InputError>(HasSubstr("250 million")));
}

TEST(FloorPlanTest, JsonRoundTripAndStrictReading) {
  FloorPlanOptions options;
  options.seed = 12345678901234ULL;
  options.rooms_per_side = 4;
  EXPECT_EQ(FloorPlanOptionsFromJson(nlohmann::json(options)), options);
  EXPECT_THAT(
      [] {
        FloorPlanOptionsFromJson(nlohmann::json{{"room_count", 3}});
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("floor_plan.room_count: unknown option")));
  EXPECT_THAT(
      [] {
        FloorPlanOptionsFromJson(nlohmann::json{{"rooms_per_side", 2.5}});
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("floor_plan.rooms_per_side: expected an integer")));
  EXPECT_THAT(
      [] {
        FloorPlanOptionsFromJson(nlohmann::json{{"seed", -1}});
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("floor_plan.seed")));
}

}  // namespace
}  // namespace slamsweep::evaluator
