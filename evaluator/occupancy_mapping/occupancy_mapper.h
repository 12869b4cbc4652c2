#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/occupancy_grid.h"
#include "evaluator/core/pose.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/occupancy_mapping/grid_extent.h"
#include "evaluator/occupancy_mapping/occupancy_mapper_options.h"
#include "evaluator/occupancy_mapping/scan_placement.h"

namespace slamsweep::evaluator::inline occupancy_mapping {

/// A map rendered from scans placed along a trajectory, and how many scans it used.
struct TrajectoryMap {
  OccupancyGrid grid;
  std::size_t scans_used = 0;
  std::size_t scans_outside_trajectory = 0;
};

/// One stage of a map being built, for animations: the map after the first scans_integrated
/// scans. `grid` is only valid during the visitor call (the next stage updates it in place).
struct MapStage {
  std::size_t stage_index = 0;
  std::size_t scans_integrated = 0;
  const OccupancyGrid& grid;
};
using MapStageVisitor = std::function<void(const MapStage& stage)>;

/// The mapper's revision: raise it whenever Build gives another map for the same scans, poses and
/// options (a changed beam model, rounding, extent rule). Maps cached on disk (the reference maps of
/// orchestrator/reference_map) carry it in their key, so a changed mapper renders them again.
inline constexpr int kOccupancyMapperRevision = 1;

/// Renders occupancy grids from laser scans and the poses they were taken from, so that an
/// algorithm that outputs only a trajectory can be scored with map metrics. Const and
/// thread-safe: each call works on its own state.
class OccupancyMapper {
 public:
  /// Throws InputError naming the offending option (ValidateMapperOptions).
  explicit OccupancyMapper(OccupancyMapperOptions options = {});

  const OccupancyMapperOptions& options() const { return options_; }

  /// options().fixed_extent if set; otherwise the smallest box on the resolution lattice (origin
  /// a multiple of resolution_m) that holds every sensor position and every beam as the mapper
  /// uses it, grown by margin_m. Throws InputError when there is nothing to map or the map would
  /// exceed kMaxMapCells.
  GridExtent Extent(std::span<const PlacedScan> scans) const;

  /// The map after integrating every scan in order. Cells never observed are kUnknown.
  OccupancyGrid Build(std::span<const PlacedScan> scans) const;
  /// Scan i taken from robot_poses[i].
  OccupancyGrid Build(std::span<const LaserScan> scans, std::span<const Pose> robot_poses) const;
  /// Scans placed by interpolating `trajectory` at their stamps (see PlaceScans).
  TrajectoryMap Build(std::span<const LaserScan> scans, const Trajectory& trajectory) const;

  /// Calls `visit` with the map after scans_integrated = stage_ends[k] scans, for each k. The
  /// map is built once, incrementally: after each stage only the cells changed since the
  /// previous one are converted, so all stages cost little more than the final map. Every
  /// stage covers the final map's extent (Extent of all scans), so frames line up. stage_ends
  /// must increase strictly and lie in [1, scans.size()] (see StagesEveryKScans and
  /// EvenlySpacedStages); otherwise InputError.
  void RenderStages(std::span<const PlacedScan> scans, std::span<const std::size_t> stage_ends,
                    const MapStageVisitor& visit) const;

 private:
  OccupancyMapperOptions options_;
};

/// Stage ends after every k-th scan: k, 2k, ..., and scan_count itself when it is not a
/// multiple of k. Throws InputError when every_k is 0.
std::vector<std::size_t> StagesEveryKScans(std::size_t scan_count, std::size_t every_k);
/// stage_count stage ends spread evenly over the scans, the last one being scan_count (fewer
/// when there are fewer scans than stages). Throws InputError when stage_count is 0.
std::vector<std::size_t> EvenlySpacedStages(std::size_t scan_count, std::size_t stage_count);

}  // namespace slamsweep::evaluator::inline occupancy_mapping
