#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/map_metrics/scorable_grid.h"

namespace slamsweep::evaluator::inline map_metrics {

/// Paper profile, section III.B. Sizes are in cells; kernels are square.
struct CornerCountOptions {
  /// Laplacian-of-Gaussian on the remapped image (known cells 1 - p, unknown 0).
  int gaussian_kernel_cells = 5;
  double gaussian_sigma_cells = 1.0;
  int laplacian_kernel_cells = 3;
  /// Structure mask: |LoG| above this fraction of its maximum.
  double structure_fraction = 0.1;
  /// 8-connected blobs of the mask with fewer cells are dropped ("small discrete dots").
  std::int64_t min_blob_cells = 5;
  /// Harris detector on the cleaned LoG, with goodFeaturesToTrack's selection.
  int harris_block_cells = 2;
  int harris_aperture_cells = 3;
  double harris_k = 0.04;
  /// Corners have a response >= quality_level * the maximum response...
  double quality_level = 0.01;
  /// ...and are at least this far apart.
  double min_distance_cells = 10.0;
};

/// Throws InputError naming the option when a value is out of range: kernels odd (Gaussian
/// 1..31, Laplacian 1..31, Harris aperture 1, 3, 5 or 7), sigma > 0, structure_fraction in
/// [0, 1), min_blob_cells >= 1, harris_block_cells in 1..32, harris_k finite,
/// quality_level in (0, 1], min_distance_cells >= 0.
void Validate(const CornerCountOptions& options);

struct CornerCount {
  /// The metric.
  std::int64_t corners = 0;
  /// Largest |LoG|; the structure mask keeps |LoG| > structure_fraction times this.
  double max_abs_log = 0.0;
  std::int64_t structure_blobs_kept = 0;
  std::int64_t structure_blobs_dropped = 0;
  /// Cells of the kept blobs: where the cleaned LoG may be non-zero.
  std::int64_t structure_cells = 0;
};

/// Corner count of a map. Throws InputError for bad options or a map that cannot be scored.
/// A map without structure (all free, for instance) has an all-zero LoG and zero corners.
CornerCount ComputeCornerCount(const OccupancyGrid& grid, const CornerCountOptions& options = {});
CornerCount ComputeCornerCount(const ScorableGrid& grid, const CornerCountOptions& options = {});
/// The same, using up `grid` (the grid `scorable` checked): its cells hold the structure image
/// instead of a new full-size one. The grid is left without cells.
CornerCount ComputeCornerCount(ScorableGrid scorable, OccupancyGrid&& grid, const CornerCountOptions& options = {});

void to_json(nlohmann::json& out, const CornerCountOptions& options);
void to_json(nlohmann::json& out, const CornerCount& result);

}  // namespace slamsweep::evaluator::inline map_metrics
