// The mapper against a simulated sequence, whose floor plan is the exact map.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>

#include "evaluator/map_metrics/occupied_proportion.h"
#include "evaluator/occupancy_mapping/occupancy_mapper.h"
#include "evaluator/simulation/simulated_sequence.h"

namespace slamsweep::evaluator {
namespace {

SimulatedSequence NoiseFreeSequence() {
  SimulationOptions options;
  options.floor_plan.rooms_per_side = 2;
  options.range_noise = {};
  options.odometry_noise = {};
  return SimulateSequence(options);
}

bool IsWall(float p) { return p > 0.5f; }

TEST(MapFromSimulationTest, MapFromTheExactGroundTruthReproducesTheWalls) {
  const SimulatedSequence sequence = NoiseFreeSequence();
  OccupancyMapperOptions options;
  options.fixed_extent = ExtentOf(sequence.floor_plan);
  const OccupancyGrid map = OccupancyMapper(options).Build(sequence.scans, sequence.ground_truth.poses());
  const OccupancyGrid& plan = sequence.floor_plan;
  ASSERT_EQ(map.width, plan.width);
  ASSERT_EQ(map.height, plan.height);

  // Precision: occupied map cells lie on (within one cell of) a wall of the plan.
  std::size_t occupied = 0, near_wall = 0;
  for (int row = 0; row < map.height; ++row) {
    for (int col = 0; col < map.width; ++col) {
      if (!IsWall(map.at(row, col))) continue;
      ++occupied;
      bool found = false;
      for (int dr = -1; dr <= 1 && !found; ++dr) {
        for (int dc = -1; dc <= 1 && !found; ++dc) {
          const int r = row + dr, c = col + dc;
          found = r >= 0 && c >= 0 && r < plan.height && c < plan.width && IsWall(plan.at(r, c));
        }
      }
      near_wall += found ? 1 : 0;
    }
  }
  ASSERT_GT(occupied, 1000u);
  EXPECT_GT(static_cast<double>(near_wall) / occupied, 0.9) << near_wall << " of " << occupied;

  // Free space: the cells the map calls free are free in the plan.
  std::size_t free = 0, free_in_plan = 0;
  for (std::size_t i = 0; i < map.CellCount(); ++i) {
    if (OccupancyGrid::IsUnknown(map.cells[i]) || map.cells[i] >= 0.5f) continue;
    ++free;
    free_in_plan += (!OccupancyGrid::IsUnknown(plan.cells[i]) && plan.cells[i] < 0.5f) ? 1 : 0;
  }
  EXPECT_GT(static_cast<double>(free_in_plan) / free, 0.99);
}

TEST(MapFromSimulationTest, OccupiedProportionOfTheExactMapCountsWallsNotFreeSpace) {
  // The paper's occupied proportion thresholds at the mean p (unknown = 0). On a map rendered from
  // the exact path, free space must end below that mean: the occupied cells are the walls and their
  // fringe, far fewer than the known cells (free space clamped at p = 0.12 counted them all).
  const SimulatedSequence sequence = NoiseFreeSequence();
  OccupancyMapperOptions options;
  options.fixed_extent = ExtentOf(sequence.floor_plan);
  const OccupancyGrid map = OccupancyMapper(options).Build(sequence.scans, sequence.ground_truth.poses());
  const OccupiedProportion proportion = ComputeOccupiedProportion(map);
  std::int64_t walls = 0;
  for (const float p : map.cells) walls += IsWall(p) ? 1 : 0;
  const std::int64_t known = proportion.total_cells - proportion.unknown_cells;
  EXPECT_GE(proportion.occupied_cells, walls);
  EXPECT_LT(proportion.occupied_cells, known / 3) << proportion.occupied_cells << " of " << known << " known";
}

TEST(MapFromSimulationTest, EveryStageEqualsAMapOfTheScansSoFarAndTheLastEqualsTheFinalMap) {
  const SimulatedSequence sequence = NoiseFreeSequence();
  const std::vector<PlacedScan> placed = PlaceScans(sequence.scans, sequence.ground_truth.poses());
  const OccupancyMapper mapper;
  const GridExtent extent = mapper.Extent(placed);
  const OccupancyGrid final_map = mapper.Build(placed);

  OccupancyMapperOptions fixed;
  fixed.fixed_extent = extent;
  const OccupancyMapper prefix_mapper(fixed);
  const std::vector<std::size_t> ends = EvenlySpacedStages(placed.size(), 7);
  ASSERT_EQ(ends.size(), 7u);
  std::size_t visits = 0;
  mapper.RenderStages(placed, ends, [&](const MapStage& stage) {
    EXPECT_EQ(stage.stage_index, visits);
    EXPECT_EQ(stage.scans_integrated, ends[visits]);
    ++visits;
    EXPECT_EQ(ExtentOf(stage.grid), extent);
    const OccupancyGrid from_scratch =
        prefix_mapper.Build(std::span<const PlacedScan>(placed).first(stage.scans_integrated));
    EXPECT_EQ(stage.grid.cells, from_scratch.cells) << "stage " << stage.stage_index;
    if (stage.scans_integrated == placed.size()) {
      EXPECT_EQ(stage.grid.cells, final_map.cells);
    }
  });
  EXPECT_EQ(visits, 7u);
}

TEST(MapFromSimulationTest, MapFromNoisyOdometryIsWorseThanFromTheTruth) {
  // The reason noise exists: odometry alone must smear the walls.
  SimulationOptions options;
  options.floor_plan.rooms_per_side = 2;
  options.odometry_noise = OdometryNoise{0.005, 0.0002, 0.005, 0.0002, 0.0, 0.0};
  const SimulatedSequence sequence = SimulateSequence(options);
  OccupancyMapperOptions mapper_options;
  mapper_options.fixed_extent = ExtentOf(sequence.floor_plan);
  const OccupancyMapper mapper(mapper_options);
  auto wall_precision = [&](const OccupancyGrid& map) {
    std::size_t occupied = 0, on_wall = 0;
    for (std::size_t i = 0; i < map.CellCount(); ++i) {
      if (!IsWall(map.cells[i])) continue;
      ++occupied;
      on_wall += IsWall(sequence.floor_plan.cells[i]) ? 1 : 0;
    }
    return static_cast<double>(on_wall) / static_cast<double>(occupied);
  };
  const double truth = wall_precision(mapper.Build(sequence.scans, sequence.ground_truth.poses()));
  const double odometry = wall_precision(mapper.Build(sequence.scans, sequence.odometry.poses()));
  EXPECT_GT(truth, odometry + 0.2) << truth << " vs " << odometry;
}

}  // namespace
}  // namespace slamsweep::evaluator
