#include "evaluator/occupancy_mapping/occupancy_mapper.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "evaluator/core/input_error.h"
#include "evaluator/occupancy_mapping/log_odds_grid.h"
#include "evaluator/occupancy_mapping/scan_beams.h"

namespace slamsweep::evaluator::inline occupancy_mapping {
namespace {

struct Bounds {
  double min_x = std::numeric_limits<double>::infinity();
  double min_y = std::numeric_limits<double>::infinity();
  double max_x = -std::numeric_limits<double>::infinity();
  double max_y = -std::numeric_limits<double>::infinity();

  void Add(double x, double y) {
    min_x = std::min(min_x, x);
    min_y = std::min(min_y, y);
    max_x = std::max(max_x, x);
    max_y = std::max(max_y, y);
  }
};

}  // namespace

OccupancyMapper::OccupancyMapper(OccupancyMapperOptions options) : options_(std::move(options)) {
  ValidateMapperOptions(options_);
}

GridExtent OccupancyMapper::Extent(std::span<const PlacedScan> scans) const {
  if (options_.fixed_extent) return *options_.fixed_extent;
  if (scans.empty()) throw InputError("nothing to map: no scans (set fixed_extent for an empty map)");
  Bounds bounds;
  BeamDirections directions;
  for (std::size_t s = 0; s < scans.size(); ++s) {
    if (scans[s].scan == nullptr) throw InputError("scan " + std::to_string(s) + ": no scan given");
    const LaserScan& scan = *scans[s].scan;
    ValidateScanGeometry(scan, s);
    directions.Update(scan);
    const SensorPose2d sensor = SensorInWorld(scans[s].robot_pose, scan);
    bounds.Add(sensor.x_m, sensor.y_m);
    const double cos_yaw = std::cos(sensor.yaw_rad);
    const double sin_yaw = std::sin(sensor.yaw_rad);
    for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
      const BeamUse use = UseBeam(scan, scan.ranges_m[i], options_.max_range_m, options_.no_return_range_m);
      if (!(use.length_m > 0.0)) continue;
      const double dx = cos_yaw * directions.cos()[i] - sin_yaw * directions.sin()[i];
      const double dy = sin_yaw * directions.cos()[i] + cos_yaw * directions.sin()[i];
      bounds.Add(sensor.x_m + use.length_m * dx, sensor.y_m + use.length_m * dy);
    }
  }
  const double resolution = options_.resolution_m;
  const double first_col = std::floor((bounds.min_x - options_.margin_m) / resolution);
  const double first_row = std::floor((bounds.min_y - options_.margin_m) / resolution);
  // +1: a point exactly on the upper lattice line still needs the cell above it.
  const double width = std::floor((bounds.max_x + options_.margin_m) / resolution) - first_col + 1.0;
  const double height = std::floor((bounds.max_y + options_.margin_m) / resolution) - first_row + 1.0;
  if (!(width * height <= static_cast<double>(kMaxMapCells))) {
    throw InputError("the map would be " + std::to_string(width) + " x " + std::to_string(height) +
                     " cells (more than " + std::to_string(kMaxMapCells) +
                     "): the trajectory spans too much space; check it, or raise resolution_m, lower max_range_m or "
                     "set fixed_extent");
  }
  GridExtent extent;
  extent.origin.x_m = first_col * resolution;
  extent.origin.y_m = first_row * resolution;
  extent.width_cells = static_cast<int>(width);
  extent.height_cells = static_cast<int>(height);
  return extent;
}

OccupancyGrid OccupancyMapper::Build(std::span<const PlacedScan> scans) const {
  LogOddsGrid log_odds(Extent(scans), options_);
  for (std::size_t i = 0; i < scans.size(); ++i) log_odds.Integrate(scans[i], i);
  OccupancyGrid grid = log_odds.MakeUnknownGrid();
  log_odds.WriteChangedCells(grid);
  return grid;
}

OccupancyGrid OccupancyMapper::Build(std::span<const LaserScan> scans, std::span<const Pose> robot_poses) const {
  return Build(PlaceScans(scans, robot_poses));
}

TrajectoryMap OccupancyMapper::Build(std::span<const LaserScan> scans, const Trajectory& trajectory) const {
  const ScanPlacement placement = PlaceScans(scans, trajectory);
  TrajectoryMap map{Build(placement.placed), placement.placed.size(), placement.outside_trajectory};
  return map;
}

void OccupancyMapper::RenderStages(std::span<const PlacedScan> scans, std::span<const std::size_t> stage_ends,
                                   const MapStageVisitor& visit) const {
  for (std::size_t k = 0; k < stage_ends.size(); ++k) {
    const std::size_t previous = k == 0 ? 0 : stage_ends[k - 1];
    if (stage_ends[k] <= previous || stage_ends[k] > scans.size()) {
      throw InputError("stage " + std::to_string(k) + " ends after scan " + std::to_string(stage_ends[k]) +
                       ", expected more than " + std::to_string(previous) + " and at most " +
                       std::to_string(scans.size()) + " (stage ends must increase)");
    }
  }
  LogOddsGrid log_odds(Extent(scans), options_);
  OccupancyGrid grid = log_odds.MakeUnknownGrid();
  std::size_t next_scan = 0;
  for (std::size_t k = 0; k < stage_ends.size(); ++k) {
    for (; next_scan < stage_ends[k]; ++next_scan) log_odds.Integrate(scans[next_scan], next_scan);
    log_odds.WriteChangedCells(grid);
    visit(MapStage{k, stage_ends[k], grid});
  }
}

std::vector<std::size_t> StagesEveryKScans(std::size_t scan_count, std::size_t every_k) {
  if (every_k == 0) throw InputError("stage interval must be at least 1 scan, got 0");
  std::vector<std::size_t> ends;
  for (std::size_t end = every_k; end <= scan_count; end += every_k) ends.push_back(end);
  if (scan_count > 0 && (ends.empty() || ends.back() != scan_count)) ends.push_back(scan_count);
  return ends;
}

std::vector<std::size_t> EvenlySpacedStages(std::size_t scan_count, std::size_t stage_count) {
  if (stage_count == 0) throw InputError("stage count must be at least 1, got 0");
  std::vector<std::size_t> ends;
  for (std::size_t k = 1; k <= stage_count; ++k) {
    // Rounded k * scan_count / stage_count, in integers so that the last end is scan_count exactly.
    const std::size_t end = (k * scan_count + stage_count / 2) / stage_count;
    if (end > 0 && (ends.empty() || end > ends.back())) ends.push_back(end);
  }
  return ends;
}

}  // namespace slamsweep::evaluator::inline occupancy_mapping
