#include "evaluator/occupancy_mapping/occupancy_mapper.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

// p = 1 - 1 / (1 + exp(l)) for the default increments, computed by hand.
constexpr float kOneHit = 0.7005671f;   // l = 0.85
constexpr float kOneMiss = 0.4013123f;  // l = -0.4

LaserScan OneBeam(float range_m, double angle_rad = 0.0) {
  LaserScan scan;
  scan.ranges_m = {range_m};
  scan.angle_min_rad = angle_rad;
  scan.angle_increment_rad = 0.01;
  scan.range_min_m = 0.05;
  scan.range_max_m = 10.0;
  return scan;
}

// A 100 x 20 grid of 0.1 m cells with its lower-left corner at the world origin.
OccupancyMapperOptions SmallFixedGrid() {
  OccupancyMapperOptions options;
  options.resolution_m = 0.1;
  options.fixed_extent = GridExtent{GridOrigin{0.0, 0.0, 0.0}, 100, 20};
  return options;
}

// Row of the cell containing world y in a grid of `height` rows of `resolution` (row 0 = top).
int RowOf(double y_m, int height, double resolution) {
  return height - 1 - static_cast<int>(std::floor(y_m / resolution));
}

TEST(OccupancyMapperTest, SingleBeamMarksTheWallCellAndFreesTheCellsBefore) {
  // Sensor in cell (col 5, y-cell 10); a wall 3 m ahead ends the beam at x = 3.55 m, cell col 35.
  const std::vector<LaserScan> scans = {OneBeam(3.0f)};
  const std::vector<Pose> poses = {Pose::Planar(0.55, 1.05, 0.0)};
  const OccupancyGrid grid = OccupancyMapper(SmallFixedGrid()).Build(scans, poses);
  ASSERT_EQ(grid.width, 100);
  ASSERT_EQ(grid.height, 20);
  const int row = RowOf(1.05, 20, 0.1);
  EXPECT_EQ(row, 9);
  for (int col = 5; col < 35; ++col) EXPECT_FLOAT_EQ(grid.at(row, col), kOneMiss) << "col " << col;
  EXPECT_FLOAT_EQ(grid.at(row, 35), kOneHit);
  for (int col = 36; col < 100; ++col) EXPECT_TRUE(OccupancyGrid::IsUnknown(grid.at(row, col))) << "col " << col;
  for (int col = 0; col < 5; ++col) EXPECT_TRUE(OccupancyGrid::IsUnknown(grid.at(row, col)));
  int known = 0;
  for (float p : grid.cells) known += OccupancyGrid::IsUnknown(p) ? 0 : 1;
  EXPECT_EQ(known, 31);
}

TEST(OccupancyMapperTest, ScanOfAPerpendicularWallMarksTheWallColumn) {
  // Wall along x = 5.05 m (the middle of column 50); sensor at (1.05, 4.05) facing +x; 61 beams
  // over +-0.6 rad with the exact distance to the wall. Every hit cell is in column 50, every
  // other cell the beams touched is free.
  LaserScan scan;
  scan.range_min_m = 0.05;
  scan.range_max_m = 10.0;
  scan.angle_min_rad = -0.6;
  scan.angle_increment_rad = 0.02;
  for (int i = 0; i < 61; ++i) {
    scan.ranges_m.push_back(static_cast<float>((5.0 - 1.05 + 0.05) / std::cos(scan.BeamAngleRad(i))));
  }
  OccupancyMapperOptions options = SmallFixedGrid();
  options.fixed_extent->height_cells = 80;
  const OccupancyGrid grid =
      OccupancyMapper(options).Build(std::vector<LaserScan>{scan}, std::vector<Pose>{Pose::Planar(1.05, 4.05, 0.0)});
  int occupied = 0;
  for (int row = 0; row < grid.height; ++row) {
    for (int col = 0; col < grid.width; ++col) {
      const float p = grid.at(row, col);
      if (OccupancyGrid::IsUnknown(p) || p < 0.5f) continue;
      ++occupied;
      EXPECT_EQ(col, 50) << "row " << row;
    }
  }
  // The ends span y = 4.05 +- 4 * tan(0.6) = 4.05 +- 2.74 m, 0.08 to 0.12 m apart.
  EXPECT_GE(occupied, 45);
  for (int col = 11; col < 50; ++col) EXPECT_LT(grid.at(RowOf(4.05, 80, 0.1), col), 0.5f);
}

TEST(OccupancyMapperTest, RepeatedScansSaturateAtTheClamps) {
  const std::vector<LaserScan> scans(50, OneBeam(3.0f));
  const std::vector<Pose> poses(50, Pose::Planar(0.55, 1.05, 0.0));
  const OccupancyGrid grid = OccupancyMapper(SmallFixedGrid()).Build(scans, poses);
  const int row = RowOf(1.05, 20, 0.1);
  EXPECT_FLOAT_EQ(grid.at(row, 35), 0.9706878f);  // l = 3.5
  EXPECT_FLOAT_EQ(grid.at(row, 20), 0.0099518f);  // l = -4.6
}

TEST(OccupancyMapperTest, DiagonalBeamsEndInTheCellOfTheirEndPoint) {
  // For many directions, the single occupied cell is the one containing the beam's end point,
  // and the free cells form an 8-connected line from the sensor to it.
  OccupancyMapperOptions options;
  options.resolution_m = 0.1;
  options.fixed_extent = GridExtent{GridOrigin{-5.0, -5.0, 0.0}, 100, 100};
  for (int k = 0; k < 72; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / 72.0 + 0.013;
    const float range = 2.0f + 0.037f * static_cast<float>(k);
    const OccupancyGrid grid = OccupancyMapper(options).Build(std::vector<LaserScan>{OneBeam(range, angle)},
                                                              std::vector<Pose>{Pose::Planar(0.02, 0.03, 0.0)});
    const double end_x = 0.02 + range * std::cos(angle);
    const double end_y = 0.03 + range * std::sin(angle);
    const int end_col = static_cast<int>(std::floor((end_x + 5.0) / 0.1));
    const int end_row = 99 - static_cast<int>(std::floor((end_y + 5.0) / 0.1));
    EXPECT_FLOAT_EQ(grid.at(end_row, end_col), kOneHit) << "beam " << k;
    int known = 0;
    int occupied = 0;
    for (float p : grid.cells) {
      known += OccupancyGrid::IsUnknown(p) ? 0 : 1;
      occupied += p > 0.5f ? 1 : 0;
    }
    EXPECT_EQ(occupied, 1) << "beam " << k;
    // An 8-connected line visits max(|dcol|, |drow|) + 1 cells, each within half a cell (along
    // the minor axis) of the segment between the centres of the first and last cell.
    const int start_col = 50, start_row = 99 - 50;
    EXPECT_EQ(known, std::max(std::abs(end_col - start_col), std::abs(end_row - start_row)) + 1) << "beam " << k;
    const double dc = end_col - start_col, dr = end_row - start_row;
    for (int row = 0; row < grid.height; ++row) {
      for (int col = 0; col < grid.width; ++col) {
        if (OccupancyGrid::IsUnknown(grid.at(row, col))) continue;
        const double off_line =
            std::abs(dr * (col - start_col) - dc * (row - start_row)) / std::max(std::abs(dc), std::abs(dr));
        EXPECT_LE(off_line, 0.5 + 1e-9) << "beam " << k << " cell " << row << "," << col;
      }
    }
  }
}

TEST(OccupancyMapperTest, NoReturnsAndFarReturnsClearWithoutAHit) {
  const std::vector<Pose> poses = {Pose::Planar(0.55, 1.05, 0.0)};
  const int row = RowOf(1.05, 20, 0.1);
  // A no-return (range_max = 10 m) clears no_return_range_m = 2 m; a return at 6 m beyond
  // max_range_m = 3 m is cut to 3 m. Neither marks a hit.
  OccupancyMapperOptions options = SmallFixedGrid();
  options.no_return_range_m = 2.0;
  options.max_range_m = 3.0;
  const struct {
    float range_m;
    int last_col;
  } cases[] = {{10.0f, 25}, {6.0f, 35}};
  for (const auto& beam : cases) {
    const OccupancyGrid grid = OccupancyMapper(options).Build(std::vector<LaserScan>{OneBeam(beam.range_m)}, poses);
    for (int col = 5; col <= beam.last_col; ++col) {
      EXPECT_FLOAT_EQ(grid.at(row, col), kOneMiss) << beam.range_m << " col " << col;
    }
    EXPECT_TRUE(OccupancyGrid::IsUnknown(grid.at(row, beam.last_col + 1))) << beam.range_m;
  }
  options.no_return_range_m = 0.0;
  const OccupancyGrid untouched = OccupancyMapper(options).Build(std::vector<LaserScan>{OneBeam(10.0f)}, poses);
  for (float p : untouched.cells) EXPECT_TRUE(OccupancyGrid::IsUnknown(p));
}

TEST(OccupancyMapperTest, UnusableBeamsAreIgnored) {
  const std::vector<Pose> poses = {Pose::Planar(0.55, 1.05, 0.0)};
  for (float range : {std::nanf(""), 0.01f, -1.0f}) {
    const OccupancyGrid grid = OccupancyMapper(SmallFixedGrid()).Build(std::vector<LaserScan>{OneBeam(range)}, poses);
    for (float p : grid.cells) ASSERT_TRUE(OccupancyGrid::IsUnknown(p)) << range;
  }
}

TEST(OccupancyMapperTest, BeamsLeavingAFixedExtentAreClippedAndMarkNoHit) {
  // The wall would be at x = 12.05 m, outside the 10 m wide grid.
  const std::vector<Pose> poses = {Pose::Planar(0.55, 1.05, 0.0)};
  const OccupancyGrid grid = OccupancyMapper(SmallFixedGrid()).Build(std::vector<LaserScan>{OneBeam(9.5f)}, poses);
  const int row = RowOf(1.05, 20, 0.1);
  for (int col = 5; col < 100; ++col) EXPECT_FLOAT_EQ(grid.at(row, col), kOneMiss) << "col " << col;
  // A sensor outside the grid still traces the part of the beam inside it.
  const std::vector<Pose> outside = {Pose::Planar(-2.05, 1.05, 0.0)};
  const OccupancyGrid entering =
      OccupancyMapper(SmallFixedGrid()).Build(std::vector<LaserScan>{OneBeam(5.0f)}, outside);
  for (int col = 0; col < 29; ++col) EXPECT_FLOAT_EQ(entering.at(row, col), kOneMiss) << "col " << col;
  EXPECT_FLOAT_EQ(entering.at(row, 29), kOneHit);
}

TEST(OccupancyMapperTest, SensorOffsetOnTheRobotIsApplied) {
  // Robot at (0.55, 1.05) facing +y; the sensor sits 1 m ahead of it (world y = 2.05), turned by
  // -pi/2, so it looks along world +x.
  LaserScan scan = OneBeam(2.0f);
  scan.sensor_pose_on_robot = Pose::Planar(1.0, 0.0, -std::numbers::pi / 2);
  OccupancyMapperOptions options = SmallFixedGrid();
  options.fixed_extent->height_cells = 40;
  const OccupancyGrid grid = OccupancyMapper(options).Build(
      std::vector<LaserScan>{scan}, std::vector<Pose>{Pose::Planar(0.55, 1.05, std::numbers::pi / 2)});
  EXPECT_FLOAT_EQ(grid.at(RowOf(2.05, 40, 0.1), 25), kOneHit);
  EXPECT_FLOAT_EQ(grid.at(RowOf(2.05, 40, 0.1), 5), kOneMiss);
}

TEST(OccupancyMapperTest, ComputedExtentHoldsEveryBeamPlusMarginOnTheLattice) {
  // Sensor at the origin, one beam of 2 m along +x, margin 1 m, 0.5 m cells: x spans [-1, 3] m
  // -> cells from floor(-2) to floor(6), 9 columns from x = -1; y spans [-1, 1] m -> 5 rows.
  OccupancyMapperOptions options;
  options.resolution_m = 0.5;
  options.margin_m = 1.0;
  const std::vector<LaserScan> scans = {OneBeam(2.0f)};
  const std::vector<PlacedScan> placed = PlaceScans(scans, std::vector<Pose>{Pose::Planar(0, 0, 0)});
  const GridExtent extent = OccupancyMapper(options).Extent(placed);
  EXPECT_DOUBLE_EQ(extent.origin.x_m, -1.0);
  EXPECT_DOUBLE_EQ(extent.origin.y_m, -1.0);
  EXPECT_EQ(extent.width_cells, 9);
  EXPECT_EQ(extent.height_cells, 5);
  const OccupancyGrid grid = OccupancyMapper(options).Build(placed);
  EXPECT_EQ(grid.width, 9);
  EXPECT_DOUBLE_EQ(grid.origin.x_m, -1.0);
  EXPECT_FLOAT_EQ(grid.at(2, 6), kOneHit);  // x = 2 m is the cell [2, 2.5), column 6
}

TEST(OccupancyMapperTest, TrajectoryOverloadInterpolatesAndCountsScansOutside) {
  // Trajectory from x = 0 at t = 0 to x = 2 at t = 2; a scan at t = 0.5 is taken from x = 0.5.
  const Trajectory trajectory({0.0, 2.0}, {Pose::Planar(0.0, 0.0, 0.0), Pose::Planar(2.0, 0.0, 0.0)});
  std::vector<LaserScan> scans = {OneBeam(3.0f), OneBeam(3.0f), OneBeam(3.0f)};
  scans[0].stamp_s = -1.0;
  scans[1].stamp_s = 0.5;
  scans[2].stamp_s = 7.0;
  OccupancyMapperOptions options;
  options.resolution_m = 0.1;
  options.fixed_extent = GridExtent{GridOrigin{-0.05, -0.05, 0.0}, 60, 1};
  const TrajectoryMap map = OccupancyMapper(options).Build(scans, trajectory);
  EXPECT_EQ(map.scans_used, 1u);
  EXPECT_EQ(map.scans_outside_trajectory, 2u);
  EXPECT_FLOAT_EQ(map.grid.at(0, 35), kOneHit);  // x = 3.5 m
  EXPECT_FLOAT_EQ(map.grid.at(0, 5), kOneMiss);  // x = 0.5 m, the sensor cell
  EXPECT_TRUE(OccupancyGrid::IsUnknown(map.grid.at(0, 4)));

  scans[1].stamp_s = 9.0;
  EXPECT_THAT([&] { OccupancyMapper(options).Build(scans, trajectory); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("[0.000000, 2.000000] s (2 poses)")));
}

TEST(OccupancyMapperTest, PlacingScansOnATrajectoryTurnsTheShortWay) {
  // Yaw 3.0 rad at t = 0 and -3.0 rad at t = 1 are 0.28 rad apart across +-pi: half way the
  // heading is pi, not 0.
  const Trajectory trajectory({0.0, 1.0}, {Pose::Planar(0, 0, 3.0), Pose::Planar(1, 0, -3.0)});
  std::vector<LaserScan> scans = {OneBeam(1.0f)};
  scans[0].stamp_s = 0.5;
  const ScanPlacement placement = PlaceScans(scans, trajectory);
  ASSERT_EQ(placement.placed.size(), 1u);
  EXPECT_NEAR(std::abs(placement.placed[0].robot_pose.Yaw()), std::numbers::pi, 1e-9);
  EXPECT_NEAR(placement.placed[0].robot_pose.position.x(), 0.5, 1e-12);
  EXPECT_EQ(placement.placed[0].scan, &scans[0]);

  const Trajectory backwards({1.0, 0.0}, {Pose(), Pose()});
  EXPECT_THAT([&] { PlaceScans(scans, backwards); }, ::testing::ThrowsMessage<InputError>(HasSubstr("pose 1")));
  EXPECT_THROW(PlaceScans(scans, Trajectory()), InputError);
}

TEST(OccupancyMapperTest, BadInputIsAnInputErrorNamingTheProblem) {
  OccupancyMapperOptions options;
  options.resolution_m = 0.0;
  EXPECT_THAT([&] { (void)OccupancyMapper{options}; }, ::testing::ThrowsMessage<InputError>(HasSubstr("resolution_m")));
  options = {};
  options.miss_log_odds = 0.2;
  EXPECT_THAT([&] { (void)OccupancyMapper{options}; },
              ::testing::ThrowsMessage<InputError>(HasSubstr("miss_log_odds")));
  options = {};
  options.no_return_range_m = -1.0;
  EXPECT_THAT([&] { (void)OccupancyMapper{options}; },
              ::testing::ThrowsMessage<InputError>(HasSubstr("no_return_range_m")));
  options = {};
  options.fixed_extent = GridExtent{GridOrigin{0, 0, 0.5}, 10, 10};
  EXPECT_THAT([&] { (void)OccupancyMapper{options}; }, ::testing::ThrowsMessage<InputError>(HasSubstr("yaw")));

  const OccupancyMapper mapper;
  const std::vector<LaserScan> two = {OneBeam(1.0f), OneBeam(1.0f)};
  EXPECT_THAT([&] { mapper.Build(two, std::vector<Pose>{Pose()}); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("2 scans and 1 poses")));
  std::vector<LaserScan> broken = two;
  broken[1].range_max_m = 0.0;
  EXPECT_THAT(
      [&] {
        mapper.Build(broken, std::vector<Pose>{Pose(), Pose()});
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("scan 1: range_max_m")));
  // A diverged trajectory must be refused, not allocated.
  EXPECT_THAT(
      [&] {
        mapper.Build(two, std::vector<Pose>{Pose(), Pose::Planar(1e6, 1e6, 0)});
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("spans too much space")));
  EXPECT_THROW(mapper.Build(std::span<const PlacedScan>{}), InputError);
  const std::vector<PlacedScan> missing = {PlacedScan{nullptr, Pose()}};
  EXPECT_THAT([&] { mapper.Build(missing); }, ::testing::ThrowsMessage<InputError>(HasSubstr("scan 0: no scan")));
}

TEST(OccupancyMapperTest, OptionsAreRecordedAsJson) {
  const nlohmann::json json = SmallFixedGrid();
  EXPECT_EQ(json.at("resolution_m"), 0.1);
  EXPECT_EQ(json.at("fixed_extent").at("width_cells"), 100);
  EXPECT_TRUE(nlohmann::json(OccupancyMapperOptions{}).at("fixed_extent").is_null());
}

}  // namespace
}  // namespace slamsweep::evaluator
