// The reference ("pseudo ground truth") map of intel, rendered from the corrected poses, has walls
// where the scans end and free space along the beams: the mapper, the CARMEN beam geometry and the
// reference poses agree with each other on a real log.

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <optional>

#include "evaluator/occupancy_mapping/occupancy_mapper.h"
#include "evaluator/sequence/carmen_sequence.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

/// Every k-th scan is checked: 182 of intel's 910 scans, spread over the whole run.
constexpr std::size_t kScanStep = 5;

struct CellIndex {
  int row = 0;
  int col = 0;
};

/// The cell holding world point (x, y), if inside the grid (row 0 = top row, see OccupancyGrid).
std::optional<CellIndex> CellAt(const OccupancyGrid& grid, double x_m, double y_m) {
  const int col = static_cast<int>(std::floor((x_m - grid.origin.x_m) / grid.resolution_m));
  const int row_from_bottom = static_cast<int>(std::floor((y_m - grid.origin.y_m) / grid.resolution_m));
  const int row = grid.height - 1 - row_from_bottom;
  if (col < 0 || col >= grid.width || row < 0 || row >= grid.height) return std::nullopt;
  return CellIndex{row, col};
}

bool Occupied(float p) { return !OccupancyGrid::IsUnknown(p) && p > 0.5f; }
bool Free(float p) { return !OccupancyGrid::IsUnknown(p) && p < 0.5f; }

bool OccupiedWithinOneCell(const OccupancyGrid& grid, CellIndex cell) {
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      const int r = cell.row + dr;
      const int c = cell.col + dc;
      if (r >= 0 && r < grid.height && c >= 0 && c < grid.width && Occupied(grid.at(r, c))) return true;
    }
  }
  return false;
}

TEST(IntelReferenceMapTest, WallsWhereTheScansEndAndFreeSpaceAlongTheBeams) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  const Sequence intel = ReadCarmenSequence(log);
  ASSERT_TRUE(intel.reference.has_value());
  ASSERT_EQ(intel.reference->size(), intel.scans.size());

  const OccupancyMapper mapper;  // 5 cm cells, returns used up to 30 m
  const OccupancyGrid map = mapper.Build(intel.scans, intel.reference->poses());

  std::size_t hits = 0;
  std::size_t end_occupied = 0;
  std::size_t end_occupied_near = 0;
  std::size_t middle_free = 0;
  for (std::size_t i = 0; i < intel.scans.size(); i += kScanStep) {
    const LaserScan& scan = intel.scans[i];
    const Pose sensor = intel.reference->poses()[i] * scan.sensor_pose_on_robot;
    const double sensor_yaw = sensor.Yaw();
    for (std::size_t b = 0; b < scan.BeamCount(); ++b) {
      const double range_m = scan.ranges_m[b];
      // Only beams the mapper marks as obstacles: returns below the scan's and the mapper's max range.
      if (!scan.IsHit(scan.ranges_m[b]) || range_m >= mapper.options().max_range_m) continue;
      const double angle = sensor_yaw + scan.BeamAngleRad(b);
      const double dx = std::cos(angle);
      const double dy = std::sin(angle);
      const std::optional<CellIndex> end =
          CellAt(map, sensor.position.x() + range_m * dx, sensor.position.y() + range_m * dy);
      const std::optional<CellIndex> middle =
          CellAt(map, sensor.position.x() + 0.5 * range_m * dx, sensor.position.y() + 0.5 * range_m * dy);
      ASSERT_TRUE(end && middle) << "scan " << i << " beam " << b << " leaves the map";
      ++hits;
      if (Occupied(map.at(end->row, end->col))) ++end_occupied;
      if (OccupiedWithinOneCell(map, *end)) ++end_occupied_near;
      if (Free(map.at(middle->row, middle->col))) ++middle_free;
    }
  }
  ASSERT_GT(hits, 20'000u);  // 182 scans x up to 180 returns: the sample is large
  const double end_share = static_cast<double>(end_occupied) / static_cast<double>(hits);
  const double near_share = static_cast<double>(end_occupied_near) / static_cast<double>(hits);
  const double middle_share = static_cast<double>(middle_free) / static_cast<double>(hits);
  RecordProperty("end_cell_occupied_share", std::to_string(end_share));
  RecordProperty("end_within_one_cell_occupied_share", std::to_string(near_share));
  RecordProperty("middle_cell_free_share", std::to_string(middle_share));
  // The end cell itself is checked within one cell (3 x 3 neighbourhood): the corrected poses are a
  // SLAM estimate with centimetre errors and a wall is seen from many poses, so its hits spread over
  // the 5 cm cells on either side of the surface; a beam grazing a wall may also end in the cell
  // next to the one that accumulated most hits. People walking through the lab (intel is a busy
  // office) leave end points in cells that later scans clear; 10 % is room for them.
  EXPECT_GE(near_share, 0.9) << "exact end cell occupied: " << end_share;
  // Half-way along a return the beam passes through space it observed as empty; only beams that
  // cross a person or a door that later closed may find an occupied cell there.
  EXPECT_GE(middle_share, 0.9);
  // The end cell itself, without the tolerance, must still be occupied in most cases (otherwise
  // the tolerance above would hide a systematic half-cell shift).
  EXPECT_GE(end_share, 0.6);
}

}  // namespace
}  // namespace slamsweep::evaluator
