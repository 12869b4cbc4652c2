#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "evaluator/occupancy_mapping/grid_extent.h"

namespace slamsweep::evaluator::inline occupancy_mapping {

/// How scans are turned into an occupancy grid (log-odds mapping, Thrun et al. ch. 9).
/// Every cell starts unknown at log-odds 0 (p = 0.5); a beam adds miss_log_odds to each cell
/// it passes and hit_log_odds to the cell it ends in; the sum is clamped to
/// [min_log_odds, max_log_odds] so that a cell can change its mind after a door opens.
/// The defaults are the usual inverse sensor model p_hit = 0.7, p_miss = 0.4, clamped to
/// p in [0.01, 0.97].
///
/// Why free space goes down to p = 0.01 (min_log_odds -4.6), as in MRPT's and GMapping's grids
/// where well-seen free space is close to 0: the paper's occupied proportion calls a cell
/// occupied when its p is above the map's mean p (unknown = 0), which is a few percent on a map
/// that is mostly unknown and free. A clamp at the textbook 0.12 lies above that mean, so every
/// known cell would count as occupied and a map rendered from the true path would score worse than
/// a SLAM program's (intel's first 300 scans: occupied / all 0.362 with 0.12, 0.139 with 0.01,
/// icp-slam's own map 0.150). A free cell still turns occupied after six hits (a door that closed).
struct OccupancyMapperOptions {
  double resolution_m = 0.05;
  double hit_log_odds = 0.85;
  double miss_log_odds = -0.4;
  double min_log_odds = -4.6;
  double max_log_odds = 3.5;
  /// Usable range: a return farther than this is cut to it and marks no obstacle (far returns
  /// are the noisiest and blur a map).
  double max_range_m = 30.0;
  /// How far a beam without return (range >= the scan's range_max_m) clears free space; 0 turns
  /// this off. Kept short because indoors a "no return" is more often glass, a black surface or
  /// a grazing angle than truly empty space: clearing 30 m would punch rays through walls.
  double no_return_range_m = 5.0;
  /// Free border around everything observed, when the extent is computed from the data.
  double margin_m = 1.0;
  /// When set, the map covers exactly this extent (beams leaving it are clipped); otherwise it
  /// is the smallest box on the resolution lattice holding every pose and beam, plus margin_m.
  std::optional<GridExtent> fixed_extent;
};

/// Log-odds are stored as 16-bit integers in units of 1/kLogOddsScale (options are rounded to
/// that), so every log-odds option must lie within +-kMaxAbsLogOdds and the increments must be
/// at least 1/kLogOddsScale.
inline constexpr double kLogOddsScale = 1000.0;
inline constexpr double kMaxAbsLogOdds = 16.0;
/// Larger maps are refused: a diverged trajectory would otherwise ask for gigabytes.
inline constexpr long long kMaxMapCells = 200'000'000;

/// Throws InputError naming the option unless: resolution_m > 0; hit_log_odds > 0 >
/// miss_log_odds; min_log_odds < 0 < max_log_odds; all within +-kMaxAbsLogOdds; max_range_m > 0;
/// no_return_range_m >= 0; margin_m >= 0; the fixed extent, if any, is valid and at most kMaxMapCells.
void ValidateMapperOptions(const OccupancyMapperOptions& options);

/// The options as recorded beside a map rendered from a trajectory.
void to_json(nlohmann::json& out, const OccupancyMapperOptions& options);

}  // namespace slamsweep::evaluator::inline occupancy_mapping
